/* Point-to-segment and point-to-triangle closest points (the constructions of §3.1 and §4.3;
 * the triangle case by Voronoi regions of the vertices, edges and face). Floating point: the
 * queries make no combinatorial decision from these values beyond "which is nearer", and the
 * callers widen every bound by a rounding slack (see query.c). */
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "sweep/sweep_internal.h"

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void sub3(const double *a, const double *b, double *out)
{
    out[0] = a[0] - b[0];
    out[1] = a[1] - b[1];
    out[2] = a[2] - b[2];
}

static double max2(double a, double b)
{
    return a > b ? a : b; /* not fmax: a libm call in this hot loop; inputs are finite */
}

static double dist2(const double *a, const double *b)
{
    double d[3];
    sub3(a, b, d);
    return dot3(d, d);
}

double fl_sweep_segment_closest(const double *p, const double *a, const double *b, double *t,
                                double *closest)
{
    double ab[3], ap[3];
    sub3(b, a, ab);
    sub3(p, a, ap);
    double len2 = dot3(ab, ab), s = dot3(ap, ab);
    /* Clamp before dividing: a repeated point (len2 = 0) gives s = 0 and t = 0. */
    if (s <= 0 || len2 <= 0) {
        s = 0;
    } else if (s >= len2) {
        s = 1;
    } else {
        s /= len2;
    }
    for (int i = 0; i < 3; i++)
        closest[i] = s == 1 ? b[i] : a[i] + s * ab[i];
    *t = s;
    return dist2(p, closest);
}

/* The nearest of the edges in `mask` (bit e: edge v[e] v[e+1]): all three for degenerate
 * triangles, whose face region is empty, and as a safe fallback when the face-region
 * barycentrics are ill-conditioned. */
static double triangle_edges_closest(const double *p, const double *v[3], int mask, double *bary,
                                     double *closest)
{
    double best = INFINITY;
    for (int e = 0; e < 3; e++) {
        if (!(mask >> e & 1)) continue;
        double t, c[3];
        double d = fl_sweep_segment_closest(p, v[e], v[(e + 1) % 3], &t, c);
        if (d < best) {
            best = d;
            bary[e] = 1 - t;
            bary[(e + 1) % 3] = t;
            bary[(e + 2) % 3] = 0;
            closest[0] = c[0];
            closest[1] = c[1];
            closest[2] = c[2];
        }
    }
    return best;
}

static void set_bary(double *bary, double u, double v, double w)
{
    bary[0] = u;
    bary[1] = v;
    bary[2] = w;
}

double fl_sweep_triangle_closest(const double *p, const double *a, const double *b, const double *c,
                                 double *bary, double *closest)
{
    const double *v[3] = {a, b, c};
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    sub3(b, a, ab);
    sub3(c, a, ac);
    sub3(p, a, ap);
    sub3(p, b, bp);
    sub3(p, c, cp);
    /* The barycentrics are scale invariant, but the products below reach the 4th power of the
     * coordinates: from edges of ~1e77 on, va, vb, vc overflowed (inf - inf = NaN) and every
     * large triangle fell back to its edges, a distance far above the true one (found by
     * fuzz/fuzz_hausdorff.c at the documented |x| <= 1e150). Rescale the differences by a power
     * of two (exact) so that they are near 1; `closest` below uses the unscaled points. */
    double m = 0;
    for (int i = 0; i < 3; i++)
        m = max2(m, max2(max2(fabs(ab[i]), fabs(ac[i])),
                         max2(fabs(ap[i]), max2(fabs(bp[i]), fabs(cp[i])))));
    if (m > 0x1p60 || (m > 0 && m < 0x1p-60)) {
        double f = ldexp(1.0, -ilogb(m));
        for (int i = 0; i < 3; i++)
            ab[i] *= f, ac[i] *= f, ap[i] *= f, bp[i] *= f, cp[i] *= f;
    }
    double d1 = dot3(ab, ap), d2 = dot3(ac, ap);
    double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
    double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
    double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
    double denom = va + vb + vc; /* = |ab x ac|^2 in exact arithmetic */
    double ab2 = dot3(ab, ab), ac2 = dot3(ac, ac);
    /* Decide degeneracy on |ab x ac|^2 computed directly: va + vb + vc cancels catastrophically
     * for a (nearly) collinear triangle and can pass the test with garbage barycentrics, giving
     * a distance far above the true one (found by fuzz/fuzz_sweep.c: a thin bounding triangle
     * whose lower bound d - eps exceeded the answer; tests/degenerate/test_sweep_degenerate.c). */
    double cx = ab[1] * ac[2] - ab[2] * ac[1], cy = ab[2] * ac[0] - ab[0] * ac[2];
    double cz = ab[0] * ac[1] - ab[1] * ac[0], cross2 = cx * cx + cy * cy + cz * cz;
    /* Relative to the LONGEST edge: a needle with one edge of 1e-15 against two of 14 passed
     * the per-angle test at a (the angle there is not small) but its va, vb, vc are rounding
     * noise, and the face solve returned the distance to a corner, 13.2 instead of 0, for a
     * query on the long edges (found by fuzz/fuzz_sweep.c as a bounding triangle with two
     * equal corners up to rounding). Area^2 <= 1e-24 L^4 puts every face point within 1e-12 L
     * of the longest edge, the same tolerance as before. */
    double bc2 = 0;
    for (int i = 0; i < 3; i++) bc2 += (ac[i] - ab[i]) * (ac[i] - ab[i]);
    double l2 = max2(max2(ab2, ac2), bc2);
    /* Outside the face's prism (some barycentric of the projection is negative) the nearest
     * point is on the boundary. A degenerate triangle (sin of its angle at a below 1e-12) also
     * goes there: its face solve would divide by (nearly) zero, and its face lies within
     * 1e-12 |ab| of its edges. Between that and well-shaped triangles the face solve loses
     * accuracy like 1/sin^2 (docs/sweep.md). */
    if (!(cross2 > 1e-24 * ab2 * ac2) || !(cross2 > 1e-24 * l2 * l2) || !(denom > 0))
        return triangle_edges_closest(p, v, 7, bary, closest);
    /* Outside a proper triangle the nearest point lies on an edge whose line separates the
     * projection from the triangle, i.e. one opposite a negative coordinate (va: edge bc,
     * vb: edge ca, vc: edge ab). A coordinate misjudged by rounding is within rounding of 0,
     * where either choice gives the same distance to rounding. */
    if (va < 0 || vb < 0 || vc < 0)
        return triangle_edges_closest(p, v, (vc < 0) | (va < 0) << 1 | (vb < 0) << 2, bary,
                                      closest);
    double s = vb / denom, t = vc / denom;
    set_bary(bary, 1 - s - t, s, t);
    for (int i = 0; i < 3; i++)
        closest[i] = a[i] + s * (b[i] - a[i]) + t * (c[i] - a[i]);
    return dist2(p, closest);
}

double fl_sweep_node_distance(const fl_sweep *s, const fl_sweep_node *node, const double *p,
                              double *bary, double *closest)
{
    double d2;
    if (s->triangles) {
        d2 = fl_sweep_triangle_closest(p, node->v, node->v + 3, node->v + 6, bary, closest);
    } else {
        double t;
        d2 = fl_sweep_segment_closest(p, node->v, node->v + 3, &t, closest);
        set_bary(bary, 1 - t, t, 0);
    }
    return sqrt(d2);
}

int fl_sweep_lift_query(const fl_sweep *s, const double *q, double *q3)
{
    for (int c = 0; c < 3; c++) {
        q3[c] = c < s->dim ? q[c] : 0;
        if (!fl_sweep_coord_ok(q3[c])) return 0;
    }
    return 1;
}

fl_status fl_sweep_alloc(int dim, int triangles, size_t elements, fl_sweep **out, fl_error *err)
{
    fl_sweep *s = calloc(1, sizeof *s);
    if (!s) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the sweep hierarchy");
    s->dim = dim;
    s->triangles = triangles;
    s->elements = elements;
    s->node_count = 2 * elements - 1;
    s->nodes = fl_alloc_array(s->node_count, sizeof *s->nodes);
    if (!s->nodes) {
        free(s);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1,
                       "out of memory for a sweep hierarchy of %zu elements", elements);
    }
    *out = s;
    return FL_OK;
}

void fl_sweep_free(fl_sweep *sweep)
{
    if (!sweep) return;
    free(sweep->nodes);
    free(sweep->box);
    free(sweep->tri);
    free(sweep);
}

int fl_sweep_dim(const fl_sweep *sweep)
{
    return sweep ? sweep->dim : 0;
}

size_t fl_sweep_element_count(const fl_sweep *sweep)
{
    return sweep ? sweep->elements : 0;
}

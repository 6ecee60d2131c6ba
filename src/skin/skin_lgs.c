/* The local gap size of a closed triangle mesh seen as a piecewise linear complex (Cheng & Tan
 * §4: lgs(x) is the radius of the smallest ball centred on x that meets an element of P not
 * containing x) and an inside test, both through a uniform grid of the triangles.
 *
 * Every vertex and edge of a closed mesh lies on a triangle, so the minimum over the elements
 * not containing x is a minimum over the triangles T near x of:
 *  - dist(x, T) when x's carrier (the element whose relative interior holds x) is not a face
 *    of T (then T does not contain x: T meets the carrier in a proper face of it);
 *  - otherwise the distance to the edges of T that do not contain the carrier (their vertices
 *    are covered by them): all three for the carrier T itself, the two others for an edge, the
 *    opposite one for a vertex. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "skin/skin_eps.h"

static void sub3(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double skin_eps_dist_segment(const double *p, const double *a, const double *b)
{
    double ab[3], ap[3];
    sub3(b, a, ab);
    sub3(p, a, ap);
    double l2 = dot3(ab, ab), s = l2 > 0 ? dot3(ap, ab) / l2 : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    double d[3] = {ap[0] - s * ab[0], ap[1] - s * ab[1], ap[2] - s * ab[2]};
    return sqrt(dot3(d, d));
}

/* Distance from p to the closed triangle abc (Ericson, Real-Time Collision Detection 5.1.5). */
static double dist_triangle(const double *p, const double *a, const double *b, const double *c)
{
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    sub3(b, a, ab);
    sub3(c, a, ac);
    sub3(p, a, ap);
    double d1 = dot3(ab, ap), d2 = dot3(ac, ap);
    if (d1 <= 0 && d2 <= 0) return sqrt(dot3(ap, ap));
    sub3(p, b, bp);
    double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
    if (d3 >= 0 && d4 <= d3) return sqrt(dot3(bp, bp));
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return skin_eps_dist_segment(p, a, b);
    sub3(p, c, cp);
    double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
    if (d6 >= 0 && d5 <= d6) return sqrt(dot3(cp, cp));
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return skin_eps_dist_segment(p, a, c);
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return skin_eps_dist_segment(p, b, c);
    double den = va + vb + vc;
    if (!(den > 0)) /* degenerate triangle: its edges */
        return fmin(skin_eps_dist_segment(p, a, b),
                    fmin(skin_eps_dist_segment(p, a, c), skin_eps_dist_segment(p, b, c)));
    double v = vb / den, w = vc / den, q[3];
    for (int i = 0; i < 3; i++) q[i] = ap[i] - v * ab[i] - w * ac[i];
    return sqrt(dot3(q, q));
}

void skin_eps_grid_free(skin_eps_grid *g)
{
    if (!g) return;
    free(g->start);
    free(g->item);
    free(g->stamp);
    memset(g, 0, sizeof *g);
}

static void cell_range(const skin_eps_grid *g, const double *lo, const double *hi, size_t *c0,
                       size_t *c1)
{
    for (int c = 0; c < 3; c++) {
        double u0 = floor((lo[c] - g->origin[c]) / g->cell);
        double u1 = floor((hi[c] - g->origin[c]) / g->cell);
        double top = (double)(g->dims[c] - 1);
        c0[c] = (size_t)(u0 < 0 ? 0 : u0 > top ? top : u0);
        c1[c] = (size_t)(u1 < 0 ? 0 : u1 > top ? top : u1);
    }
}

static void tri_box(const fl_mesh *m, size_t f, double *lo, double *hi)
{
    for (int c = 0; c < 3; c++) {
        lo[c] = HUGE_VAL;
        hi[c] = -HUGE_VAL;
        for (int j = 0; j < 3; j++) {
            double x = m->xyz[3 * (size_t)m->tri[3 * f + j] + c];
            lo[c] = fmin(lo[c], x);
            hi[c] = fmax(hi[c], x);
        }
    }
}

/* Cells of about `reach` (so a query within reach looks at 27 cells), coarser when the box
 * would need more than ~2^21 cells or a triangle more than ~64 cells of registration on
 * average; CSR lists of the triangles whose box meets each cell. */
fl_status skin_eps_grid_build(const fl_mesh *m, double reach, skin_eps_grid *g, fl_error *err)
{
    memset(g, 0, sizeof *g);
    g->mesh = m;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (size_t i = 0; i < m->vertex_count; i++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], m->xyz[3 * i + c]);
            hi[c] = fmax(hi[c], m->xyz[3 * i + c]);
        }
    double span = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2]));
    double cell = fmax(reach, span / 128.0);
    if (!(cell > 0)) cell = 1;
    for (;; cell *= 1.5) {
        double regs = 0;
        for (size_t f = 0; f < m->triangle_count && regs < 1e8; f++) {
            double a[3], b[3];
            tri_box(m, f, a, b);
            double k = 1;
            for (int c = 0; c < 3; c++) k *= floor((b[c] - a[c]) / cell) + 2;
            regs += k;
        }
        if (regs <= 64.0 * (double)m->triangle_count + 1e6) break;
    }
    g->cell = cell;
    size_t cells = 1;
    for (int c = 0; c < 3; c++) {
        g->origin[c] = lo[c] - cell;
        g->dims[c] = (size_t)((hi[c] - lo[c]) / cell) + 3;
        cells *= g->dims[c];
    }
    g->start = fl_calloc_array(cells + 1, sizeof(size_t));
    g->stamp = fl_calloc_array(m->triangle_count ? m->triangle_count : 1, sizeof(uint32_t));
    if (!g->start || !g->stamp) goto nomem;
    for (int pass = 0; pass < 2; pass++) {
        for (size_t f = 0; f < m->triangle_count; f++) {
            double a[3], b[3];
            size_t c0[3], c1[3];
            tri_box(m, f, a, b);
            cell_range(g, a, b, c0, c1);
            for (size_t z = c0[2]; z <= c1[2]; z++)
                for (size_t y = c0[1]; y <= c1[1]; y++)
                    for (size_t x = c0[0]; x <= c1[0]; x++) {
                        size_t id = (z * g->dims[1] + y) * g->dims[0] + x;
                        if (pass == 0)
                            g->start[id + 1]++;
                        else
                            g->item[g->start[id]++] = (uint32_t)f;
                    }
        }
        if (pass == 0) {
            for (size_t i = 0; i < cells; i++) g->start[i + 1] += g->start[i];
            g->item = fl_alloc_array(g->start[cells] ? g->start[cells] : 1, sizeof(uint32_t));
            if (!g->item) goto nomem;
        } else {
            for (size_t i = cells; i > 0; i--) g->start[i] = g->start[i - 1];
            g->start[0] = 0;
        }
    }
    return FL_OK;
nomem:
    skin_eps_grid_free(g);
    return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (triangle grid)");
}

static int has_vertex(const uint32_t *t, uint32_t v)
{
    return t[0] == v || t[1] == v || t[2] == v;
}

/* The lgs contribution of triangle f for a point p with carrier (kind, ids). */
static double tri_gap(const fl_mesh *m, size_t f, const double *p, int kind, const uint32_t *ids,
                      size_t carrier_tri)
{
    const uint32_t *t = m->tri + 3 * f;
    const double *x[3] = {m->xyz + 3 * (size_t)t[0], m->xyz + 3 * (size_t)t[1],
                          m->xyz + 3 * (size_t)t[2]};
    int face = kind == 0   ? has_vertex(t, ids[0])
               : kind == 1 ? has_vertex(t, ids[0]) && has_vertex(t, ids[1])
                           : f == carrier_tri;
    if (!face) return dist_triangle(p, x[0], x[1], x[2]);
    double d = HUGE_VAL;
    for (int j = 0; j < 3; j++) {
        uint32_t a = t[j], b = t[(j + 1) % 3];
        int contains = kind == 0 ? (a == ids[0] || b == ids[0])
                       : kind == 1
                           ? ((a == ids[0] && b == ids[1]) || (a == ids[1] && b == ids[0]))
                           : 0;
        if (!contains) d = fmin(d, skin_eps_dist_segment(p, x[j], x[(j + 1) % 3]));
    }
    return d;
}

double skin_eps_lgs(skin_eps_grid *g, const double *p, int kind, const uint32_t *ids,
                    size_t carrier_tri, double reach)
{
    double lo[3], hi[3], best = reach;
    for (int c = 0; c < 3; c++) {
        lo[c] = p[c] - reach;
        hi[c] = p[c] + reach;
    }
    size_t c0[3], c1[3];
    cell_range(g, lo, hi, c0, c1);
    if (++g->epoch == 0) { /* wrapped: reset the stamps */
        memset(g->stamp, 0, g->mesh->triangle_count * sizeof(uint32_t));
        g->epoch = 1;
    }
    for (size_t z = c0[2]; z <= c1[2]; z++)
        for (size_t y = c0[1]; y <= c1[1]; y++)
            for (size_t x = c0[0]; x <= c1[0]; x++) {
                size_t id = (z * g->dims[1] + y) * g->dims[0] + x;
                for (size_t i = g->start[id]; i < g->start[id + 1]; i++) {
                    uint32_t f = g->item[i];
                    if (g->stamp[f] == g->epoch) continue;
                    g->stamp[f] = g->epoch;
                    best = fmin(best, tri_gap(g->mesh, f, p, kind, ids, carrier_tri));
                }
            }
    return best;
}

/* Ray parity along +x through the grid row of p, with Moller-Trumbore in doubles. A hit too
 * close to an edge of a triangle or to p itself makes the parity unreliable: -1. */
static int ray_parity(skin_eps_grid *g, const double *p)
{
    const fl_mesh *m = g->mesh;
    size_t c0[3], c1[3];
    double hi[3] = {HUGE_VAL, p[1], p[2]};
    cell_range(g, p, hi, c0, c1);
    if (++g->epoch == 0) {
        memset(g->stamp, 0, m->triangle_count * sizeof(uint32_t));
        g->epoch = 1;
    }
    int parity = 0;
    for (size_t x = c0[0]; x < g->dims[0]; x++) {
        size_t id = (c0[2] * g->dims[1] + c0[1]) * g->dims[0] + x;
        for (size_t i = g->start[id]; i < g->start[id + 1]; i++) {
            uint32_t f = g->item[i];
            if (g->stamp[f] == g->epoch) continue;
            g->stamp[f] = g->epoch;
            const uint32_t *t = m->tri + 3 * (size_t)f;
            const double *a = m->xyz + 3 * (size_t)t[0];
            double e1[3], e2[3], s[3];
            sub3(m->xyz + 3 * (size_t)t[1], a, e1);
            sub3(m->xyz + 3 * (size_t)t[2], a, e2);
            sub3(p, a, s);
            /* direction (1, 0, 0): h = d x e2 = (0, -e2z, e2y) */
            double h[3] = {0, -e2[2], e2[1]};
            double det = dot3(e1, h);
            double scale = sqrt(dot3(e1, e1) * dot3(e2, e2));
            if (fabs(det) <= 1e-12 * scale) continue; /* parallel to the ray: no transversal hit */
            double u = dot3(s, h) / det;
            double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2],
                           s[0] * e1[1] - s[1] * e1[0]};
            double v = q[0] / det; /* dot(d, q) with d = (1, 0, 0) */
            double tt = dot3(e2, q) / det;
            const double tol = 1e-9;
            if (u < -tol || v < -tol || u + v > 1 + tol || tt < -tol * g->cell) continue;
            if (u < tol || v < tol || u + v > 1 - tol || tt < tol * g->cell) return -1;
            parity ^= 1;
        }
    }
    return parity;
}

int skin_eps_inside(skin_eps_grid *g, const double *p)
{
    for (int c = 0; c < 3; c++)
        if (!(p[c] > g->origin[c] + g->cell &&
              p[c] < g->origin[c] + (double)(g->dims[c] - 1) * g->cell))
            return 0; /* outside the mesh's box (or NaN) */
    int r = ray_parity(g, p);
    if (r >= 0) return r;
    return skin_eps_winding(g->mesh, p) > 0.5;
}

/* Generalised winding number of the closed oriented mesh around x (Van Oosterom & Strackee's
 * solid angle per triangle): 1 inside, 0 outside, exact up to rounding away from the surface.
 * It decides the orthocentres whose ray parity was ambiguous (skin_eps_inside). */
double skin_eps_winding(const fl_mesh *m, const double x[3])
{
    double sum = 0;
    for (size_t f = 0; f < m->triangle_count; f++) {
        double a[3], b[3], c[3];
        const uint32_t *t = m->tri + 3 * f;
        for (int i = 0; i < 3; i++) {
            a[i] = m->xyz[3 * t[0] + i] - x[i];
            b[i] = m->xyz[3 * t[1] + i] - x[i];
            c[i] = m->xyz[3 * t[2] + i] - x[i];
        }
        double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        double lb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
        double lc = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                     a[2] * (b[0] * c[1] - b[1] * c[0]);
        double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        double bc = b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
        double ca = c[0] * a[0] + c[1] * a[1] + c[2] * a[2];
        double den = la * lb * lc + ab * lc + bc * la + ca * lb;
        sum += 2.0 * atan2(det, den);
    }
    return sum / (4.0 * 3.14159265358979323846);
}

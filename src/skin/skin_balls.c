/* The ball sets of the ε-approximation (Cheng & Tan §5, §6.2): the surface balls B, the
 * orthogonal balls B_perp of the power vertices inside the object, and B*.
 *
 * B here is NOT the paper's ε-subdividing alpha complex (§4.2, Algorithm 1, driven by the local
 * gap size): it is a conforming uniform sampling of the surface with one radius rho. The
 * paper's guarantees (Theorems 14, 18) therefore do not apply as proofs; skin_approx.c verifies
 * the result instead (certified Hausdorff distance and Euler characteristic). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "skin/skin_eps.h"

/* ---- surface sampling --------------------------------------------------------------------- */

static double circumradius(const double *a, const double *b, const double *c)
{
    double u[3], v[3], w[3];
    for (int i = 0; i < 3; i++) {
        u[i] = b[i] - a[i];
        v[i] = c[i] - a[i];
        w[i] = c[i] - b[i];
    }
    double cr[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                    u[0] * v[1] - u[1] * v[0]};
    double area2 = sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
    double lu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    double lv = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    double lw = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    /* R = abc / (4 area) = abc / (2 |u x v|); a degenerate triangle gets its longest side. */
    double m = fmax(lu, fmax(lv, lw));
    if (!(area2 > 0)) return m;
    return fmin(lu * lv * lw / (2.0 * area2), 1e300);
}

static int cmp_edge(const void *pa, const void *pb)
{
    const uint32_t *a = pa, *b = pb;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

static int push_ball(fl_vec *v, const double *a, const double *b, const double *c, double s,
                     double u, double w)
{
    double x[4];
    for (int i = 0; i < 3; i++) x[i] = a[i] + s * (b[i] - a[i]) + u * (c[i] - a[i]);
    x[3] = w;
    return fl_vec_push(v, x, 1);
}

/* Every triangle is split into k^2 triangles similar to it (k from the largest circumradius),
 * so shared edges are split alike and the samples conform. A point of a triangle lies within
 * its circumradius of the nearest corner, hence balls of radius rho >= R / k at the samples
 * cover the surface. Each mesh vertex, edge and face contributes its own samples once. */
fl_status skin_eps_surface_balls(const fl_mesh *m, double rho, fl_balls *out, fl_error *err)
{
    double rmax = 0;
    const double *p = m->xyz;
    for (size_t f = 0; f < m->triangle_count; f++) {
        const uint32_t *t = m->tri + 3 * f;
        rmax = fmax(rmax, circumradius(p + 3 * t[0], p + 3 * t[1], p + 3 * t[2]));
    }
    double kd = ceil(rmax / (0.95 * rho));
    if (kd < 1) kd = 1;
    if (!(kd < 4096) || kd * kd * (double)m->triangle_count > 2e7)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "skin: epsilon %g is too small for this mesh (%g samples a triangle)",
                       rho / 0.8, kd * kd);
    size_t k = (size_t)kd;
    uint32_t *edge = fl_alloc_array(m->triangle_count * 3, 2 * sizeof(uint32_t));
    char *used = calloc(m->vertex_count ? m->vertex_count : 1, 1);
    fl_vec v;
    fl_vec_init(&v, 4 * sizeof(double));
    if (!edge || !used) goto nomem;
    size_t ne = 0;
    for (size_t f = 0; f < m->triangle_count; f++) {
        for (int j = 0; j < 3; j++) {
            uint32_t a = m->tri[3 * f + j], b = m->tri[3 * f + (j + 1) % 3];
            edge[2 * ne] = a < b ? a : b;
            edge[2 * ne + 1] = a < b ? b : a;
            ne++;
            used[a] = 1;
        }
    }
    qsort(edge, ne, 2 * sizeof(uint32_t), cmp_edge);
    double w = rho * rho;
    for (size_t i = 0; i < m->vertex_count; i++)
        if (used[i] && push_ball(&v, p + 3 * i, p + 3 * i, p + 3 * i, 0, 0, w)) goto nomem;
    for (size_t e = 0; e < ne; e++) {
        if (e > 0 && !cmp_edge(edge + 2 * e, edge + 2 * (e - 1))) continue;
        const double *a = p + 3 * edge[2 * e], *b = p + 3 * edge[2 * e + 1];
        for (size_t i = 1; i < k; i++)
            if (push_ball(&v, a, b, a, (double)i / (double)k, 0, w)) goto nomem;
    }
    for (size_t f = 0; f < m->triangle_count; f++) {
        const uint32_t *t = m->tri + 3 * f;
        for (size_t i = 1; i < k; i++)
            for (size_t j = 1; i + j < k; j++)
                if (push_ball(&v, p + 3 * t[0], p + 3 * t[1], p + 3 * t[2], (double)i / (double)k,
                              (double)j / (double)k, w))
                    goto nomem;
    }
    free(edge);
    free(used);
    out->count = v.count;
    out->xyzw = fl_vec_release(&v);
    return FL_OK;
nomem:
    free(edge);
    free(used);
    fl_vec_free(&v);
    return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory sampling the surface");
}

/* ---- inside test ---------------------------------------------------------------------------- */

/* Generalised winding number of the closed oriented mesh around x (Van Oosterom & Strackee's
 * solid angle per triangle): 1 inside, 0 outside, exact up to rounding away from the surface.
 * Only points near the surface (orthocentres of nearly flat tetrahedra) can be misjudged, and
 * their balls are tiny; the verification measures the result either way. */
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

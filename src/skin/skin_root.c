/* Mesh vertices on the skin: the zero of G on a grid edge, the distance estimate of the
 * vertices to the skin, and handing the mesh over; shared by the uniform mesher (skin_mesh.c)
 * and the graded one (skin_graded.c).
 *
 * Why a closed form is exact here: on the mixed cell mu_X = (1-t) X + t nu_X the skin function
 * is X's quadric G = |q|^2 - t/(1-t) |p|^2 + t w_X, with x - f = p + q split parallel and
 * orthogonal to aff X (docs/skin.md, "The skin function"). p and q are affine in x, so along a
 * segment x = a + s d inside mu_X, G is a quadratic polynomial in s. mu_X is convex (a Minkowski
 * sum of two convex polytopes), so a segment whose two ends lie in mu_X lies in it, and the
 * zero of G on it is a root of that polynomial, fixed by three values of that cell's G (no walk;
 * skin_combination_value, which does not cancel like the quadric's coefficients). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_internal.h"
#include "skin/skin_internal.h"

static void at(const double a[3], const double d[3], double s, double x[3])
{
    for (int k = 0; k < 3; k++)
        x[k] = a[k] + s * d[k];
}

/* The coefficients of G(a + (lo + u (hi - lo)) d) = c[0] u^2 + c[1] u + c[2], u in [0, 1], on
 * the mixed cell of simplex id, which holds that part of the line. G is a quadratic there, so
 * its values at u = 0, 1/2, 1 determine it; they come from skin_simplex_value, not from the
 * quadric's
 * coefficients, which cancel badly when X's focus is far (round 18). */
static void quadric_line(const fl_skin_function *sk, uint32_t id, const double a[3],
                         const double d[3], double lo, double hi, double c[3])
{
    double x[3];
    at(a, d, lo, x);
    double g0 = skin_simplex_value(sk, &sk->simplex[id], x, NULL);
    at(a, d, 0.5 * (lo + hi), x);
    double gm = skin_simplex_value(sk, &sk->simplex[id], x, NULL);
    at(a, d, hi, x);
    double g1 = skin_simplex_value(sk, &sk->simplex[id], x, NULL);
    c[0] = 2 * (g0 - 2 * gm + g1);
    c[1] = g1 - g0 - c[0];
    c[2] = g0;
}

static double poly(const double c[3], double s)
{
    return (c[0] * s + c[1]) * s + c[2];
}

/* The root of c[0] s^2 + c[1] s + c[2] in [lo, hi], whose ends have values of opposite signs in
 * exact arithmetic: the closed form (the cancellation-free pair of formulas), checked
 * against the bracket, then Newton steps kept inside it; bisection on the polynomial when
 * rounding put both closed-form roots outside. */
static double quadratic_root(const double c[3], double lo, double hi)
{
    double plo = poly(c, lo), phi = poly(c, hi), s = 0.5 * (lo + hi);
    /* no sign change: rounding (an end located in this cell within the walk's slack, G there
     * a few ulps from 0); the root is at the end nearer to zero */
    if ((plo > 0) == (phi > 0) || (plo < 0) == (phi < 0)) return fabs(plo) <= fabs(phi) ? lo : hi;
    int up = plo < 0; /* the polynomial rises from lo to hi */
    double disc = c[1] * c[1] - 4 * c[0] * c[2];
    disc = disc > 0 ? sqrt(disc) : 0;
    double qr = -0.5 * (c[1] + (c[1] < 0 ? -disc : disc));
    double r1 = c[0] != 0 ? qr / c[0] : HUGE_VAL, r2 = qr != 0 ? c[2] / qr : HUGE_VAL;
    double pad = 1e-9 * (hi - lo);
    if (r1 >= lo - pad && r1 <= hi + pad)
        s = r1;
    else if (r2 >= lo - pad && r2 <= hi + pad)
        s = r2;
    else { /* rounding: bisect the polynomial */
        double a = lo, b = hi;
        for (int it = 0; it < 200 && b - a > 4 * DBL_EPSILON * (fabs(a) + fabs(b)); it++) {
            double m = 0.5 * (a + b);
            if ((poly(c, m) < 0) == up)
                a = m;
            else
                b = m;
        }
        return 0.5 * (a + b);
    }
    s = fmin(hi, fmax(lo, s));
    for (int it = 0; it < 2; it++) { /* polish: the closed form loses digits when c[0] ~ 0 */
        double der = 2 * c[0] * s + c[1];
        if (!(der != 0)) break;
        double ns = s - poly(c, s) / der;
        if (!(ns >= lo && ns <= hi) || !(fabs(poly(c, ns)) < fabs(poly(c, s)))) break;
        s = ns;
    }
    return s;
}

/* Regula falsi (Illinois) with a bisection step whenever a step shrinks the bracket by less
 * than half, until the bracket no longer shrinks, or until its two ends lie in one mixed cell
 * (then the closed form finishes). The end with the smaller |G| is the answer. */
void skin_edge_root(const fl_skin_function *g, const double a[3], const double b[3], uint32_t ca,
                    uint32_t cb, uint32_t *hint, double x[3], size_t *evaluations)
{
    uint32_t own = hint ? *hint : 0, *h = hint ? hint : &own;
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, coef[3];
    if (ca != SKIN_NO_CELL && ca == cb) {
        quadric_line(g, ca, a, d, 0, 1, coef);
        at(a, d, quadratic_root(coef, 0, 1), x);
        return;
    }
    /* parameter s in [lo, hi] along a -> b; G(lo) < 0 <= G(hi) */
    double lo = 0, hi = 1, glo, ghi;
    uint32_t clo = skin_locate(g, a, h, &glo), chi = skin_locate(g, b, h, &ghi);
    size_t ev = 2;
    int side = 0;
    for (int it = 0; it < 200 && glo < 0 && ghi > 0; it++) {
        if (clo != SKIN_NO_CELL && clo == chi) {
            quadric_line(g, clo, a, d, lo, hi, coef);
            at(a, d, lo + (hi - lo) * quadratic_root(coef, 0, 1), x);
            *evaluations += ev;
            return;
        }
        double width = hi - lo;
        double s_new = lo + (hi - lo) * (-glo / (ghi - glo));
        if (!(s_new > lo && s_new < hi)) s_new = 0.5 * (lo + hi);
        at(a, d, s_new, x);
        double gx;
        uint32_t cx = skin_locate(g, x, h, &gx);
        ev++;
        if (gx < 0) {
            lo = s_new, glo = gx, clo = cx;
            if (side == -1) ghi *= 0.5; /* Illinois: the stale end would stall regula falsi */
            side = -1;
        } else {
            hi = s_new, ghi = gx, chi = cx;
            if (side == 1) glo *= 0.5;
            side = 1;
        }
        if (hi - lo > 0.5 * width) { /* slow step: bisect once */
            double mid = 0.5 * (lo + hi), gm;
            if (mid <= lo || mid >= hi) break;
            at(a, d, mid, x);
            uint32_t cm = skin_locate(g, x, h, &gm);
            ev++;
            if (gm < 0)
                lo = mid, glo = gm, clo = cm;
            else
                hi = mid, ghi = gm, chi = cm;
            side = 0;
        }
        if (!(hi - lo > 4 * DBL_EPSILON)) break;
    }
    /* the end with the smaller |G| (the halved Illinois values are not G: re-evaluate) */
    double xl[3], xh[3], gl, gh;
    at(a, d, lo, xl);
    at(a, d, hi, xh);
    skin_locate(g, xl, h, &gl);
    skin_locate(g, xh, h, &gh);
    *evaluations += ev + 2;
    memcpy(x, fabs(gl) <= fabs(gh) ? xl : xh, sizeof(xl));
}

/* |G(v)| / |grad G(v)| at one point: the gradient of the cell's quadric, 2 (v - z*). */
static double offset_at(const fl_skin_function *g, const double *v, double h, uint32_t *hint,
                        size_t *ev)
{
    double val, grad[3];
    uint32_t c = skin_locate(g, v, hint, &val);
    ++*ev;
    if (c != SKIN_NO_CELL) {
        skin_simplex_value(g, &g->simplex[c], v, grad);
    } else {
        double d = 1e-5 * h;
        for (int k = 0; k < 3; k++) {
            double a[3] = {v[0], v[1], v[2]}, b[3] = {v[0], v[1], v[2]}, ga, gb;
            a[k] += d;
            b[k] -= d;
            skin_locate(g, a, hint, &ga);
            skin_locate(g, b, hint, &gb);
            grad[k] = (ga - gb) / (2 * d);
        }
        *ev += 6;
    }
    return fabs(val) / sqrt(grad[0] * grad[0] + grad[1] * grad[1] + grad[2] * grad[2]);
}

double skin_vertex_offset(const fl_skin_function *g, const double *xyz, size_t count, double h,
                          size_t *evaluations)
{
    double worst = 0;
    uint32_t hint = 0;
    /* the vertices in a spatial order (BRIO: Hilbert order in rounds), so that each walk
     * starts next to the previous vertex's cell; the meshers number them in the order of their
     * cells or tetrahedra, which for the graded mesher is not space's (sphere.off's B* at grade
     * 2: 322 k far restarts for 322 k vertices; round 15). Without memory: the given order. */
    uint32_t *order = NULL;
    fl_error e;
    if (count < UINT32_MAX && count > 0) {
        order = fl_alloc_array(count, sizeof *order);
        if (order && fl_dt_brio_order(xyz, NULL, count, 3, order, &e) != FL_OK) {
            free(order);
            order = NULL;
        }
    }
    for (size_t i = 0; i < count; i++) {
        double off = offset_at(g, xyz + 3 * (order ? order[i] : i), h, &hint, evaluations);
        if (!(off <= worst)) worst = off;
    }
    free(order);
    return worst;
}

void skin_hand_over(fl_vec *xyz, fl_vec *tri, fl_mesh *out)
{
    out->vertex_count = xyz->count;
    out->triangle_count = tri->count;
    out->xyz = fl_vec_release(xyz);
    out->tri = fl_vec_release(tri);
}

/* Exact sign of a link test of the mixed-cell walk (skin_cell.c).
 *
 * For a simplex X = (z_0 .. z_k), k <= 2, a ball b of its link and a query point x, the walk
 * asks whether v = f + q/t (x - f = p + q, q orthogonal to aff X, f the focus of X) satisfies
 * pi_b(v) >= pi_X(v). With a = z_0, e_i = z_i - a, e_b = z_b - a, d = x - a, the Gram matrix
 * G_ij = e_i.e_j, r_i = (|e_i|^2 - w_i + w_0) / 2 (same for r_b), u_i = t r_i - e_i.d and
 * c = t r_b - e_b.d, the test value the walk computes in floating point is
 *     H = t (pi_b(v) - pi_X(v)) = 2 (c - u^T G^-1 g),   g_i = e_i.e_b,
 * and by the Schur complement det [[G, g], [u^T, c]] = det G (c - u^T G^-1 g), det G > 0. So
 * sign H = sign det M with M that (k+1) x (k+1) matrix of dot products of coordinate
 * differences: a polynomial in the input doubles, evaluated here in big integers (the inputs
 * scaled by one power of two into integers, the weights by its square, the last row by the
 * power of two that makes t an odd integer). The walk uses it where the floating-point test is
 * within its rounding band: on the faces of B*'s nearly flat tetrahedra the link test of the
 * fourth ball is almost constant along aff nu_X, so the band covers most of the line
 * (docs/skin.md, "The bunny", round 11). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "predicates/predicates_internal.h"
#include "skin/skin_internal.h"

/* Largest integer length (bits) of an input after scaling that the exact test accepts; beyond
 * it the caller falls back to the scan (only absurd exponent ranges get there). */
#define EXACT_MAX_BITS 4200

typedef struct arena {
    uint32_t *pool;
    int limbs, used, cap;
} arena;

static fl_big take(arena *A)
{
    fl_big r = {A->pool + (size_t)A->used++ * (size_t)A->limbs, 0, 0};
    return r;
}

static void dot(arena *A, fl_big *r, const fl_big *u, const fl_big *v)
{
    fl_big p = take(A);
    r->len = 0;
    r->neg = 0;
    for (int c = 0; c < 3; c++) {
        fl_big_mul(&p, &u[c], &v[c]);
        fl_big_add(r, r, &p);
    }
    A->used--;
}

static int low_exp_min(double v, int *emin)
{
    if (v == 0) return 0;
    if (!isfinite(v)) return -1;
    int e = fl_big_low_exponent(v);
    if (e < *emin) *emin = e;
    return 0;
}

/* A floating-point value with a bound on its distance to the exact value of the same
 * expression: every operation adds its own rounding (U |result|) and the propagated bounds,
 * and the sum of bounds is inflated by (1 + 8U) for the rounding of the bound itself. */
typedef struct ev {
    double v, e;
} ev;
#define EV_U (DBL_EPSILON / 2)

static ev ev_in(double v)
{
    return (ev){v, 0};
}

static ev ev_add(ev a, ev b, double sg)
{
    double v = a.v + sg * b.v;
    return (ev){v, (a.e + b.e + EV_U * fabs(v)) * (1 + 8 * EV_U)};
}

static ev ev_mul(ev a, ev b)
{
    double v = a.v * b.v;
    /* 0x1p-1070: the rounding of a product in the subnormal range is absolute */
    return (ev){v, (fabs(a.v) * b.e + fabs(b.v) * a.e + a.e * b.e + EV_U * fabs(v) + 0x1p-1070) *
                       (1 + 8 * EV_U)};
}

static ev ev_dot(const ev *u, const ev *w)
{
    ev r = ev_mul(u[0], w[0]);
    r = ev_add(r, ev_mul(u[1], w[1]), 1);
    return ev_add(r, ev_mul(u[2], w[2]), 1);
}

/* The sign of skin_link_sign_exact's determinant in floating point with a bound on its error
 * (the same matrix with its last row multiplied by the positive 2^et: t (|e_j|^2 - w_j + w_0)
 * - 2 e_j.d), or 0 when the bound does not decide it. Inputs of magnitude 0 or in
 * [2^-100, 2^100] keep every product of the degree-6 determinant far from overflow, and a
 * product's underflow is covered by its absolute term; other inputs are decided exactly. */
static int link_sign_filter(const double *const *pts, int k, double t)
{
    for (int i = 0; i < 5; i++)
        for (int c = 0; c < 4 && (c < 3 || i < 4); c++) {
            double v = fabs(pts[i][c]);
            if (!(v <= 0x1p100) || (v != 0 && v < 0x1p-100)) return 0;
        }
    ev E[3][3], D[3], M[3][3], tt = ev_in(t);
    int rowof[3] = {1, 2, 3};
    rowof[k] = 3;
    for (int j = 0; j <= k; j++)
        for (int c = 0; c < 3; c++)
            E[j][c] = ev_add(ev_in(pts[rowof[j]][c]), ev_in(pts[0][c]), -1);
    for (int c = 0; c < 3; c++)
        D[c] = ev_add(ev_in(pts[4][c]), ev_in(pts[0][c]), -1);
    for (int i = 0; i < k; i++)
        for (int j = 0; j <= k; j++)
            M[i][j] = ev_dot(E[i], E[j]);
    for (int j = 0; j <= k; j++) {
        ev q = ev_add(ev_dot(E[j], E[j]), ev_in(pts[rowof[j]][3]), -1);
        q = ev_add(q, ev_in(pts[0][3]), 1);
        ev dd = ev_dot(E[j], D);
        M[k][j] = ev_add(ev_mul(tt, q), ev_add(dd, dd, 1), -1);
    }
    ev det;
    if (k == 0) {
        det = M[0][0];
    } else if (k == 1) {
        det = ev_add(ev_mul(M[0][0], M[1][1]), ev_mul(M[0][1], M[1][0]), -1);
    } else {
        static const int cof[3][2] = {{1, 2}, {0, 2}, {0, 1}};
        det = ev_in(0);
        for (int j = 0; j < 3; j++) {
            int c0 = cof[j][0], c1 = cof[j][1];
            ev m2 = ev_add(ev_mul(M[1][c0], M[2][c1]), ev_mul(M[1][c1], M[2][c0]), -1);
            det = ev_add(det, ev_mul(M[0][j], m2), j == 1 ? -1 : 1);
        }
    }
    if (!(isfinite(det.v) && isfinite(det.e))) return 0;
    return det.v > det.e ? 1 : det.v < -det.e ? -1 : 0;
}

int skin_link_sign_exact(const double *balls, const skin_simplex *s, uint32_t b,
                         const double x[3], double t)
{
    if (s->k <= 2 && t > 0 && t < 1) {
        const double *zb = balls + 4 * (size_t)b;
        const double *z0 = balls + 4 * (size_t)s->ball[0];
        const double *pts[5] = {z0, s->k > 0 ? balls + 4 * (size_t)s->ball[1] : zb,
                                s->k > 1 ? balls + 4 * (size_t)s->ball[2] : zb, zb, x};
        int sg = skin_link_filter_off ? 0 : link_sign_filter(pts, s->k, t);
        if (sg) return sg;
    }
    return skin_link_sign_big(balls, s, b, x, t);
}

int skin_link_filter_off;

int skin_link_sign_big(const double *balls, const skin_simplex *s, uint32_t b,
                       const double x[3], double t)
{
    int k = s->k;
    if (k > 2 || !(t > 0 && t < 1)) return 2;
    const double *z[4], *zb = balls + 4 * (size_t)b;
    for (int i = 0; i <= k; i++)
        z[i] = balls + 4 * (size_t)s->ball[i];
    /* the common scale: every coordinate an integer multiple of 2^emin, every weight of
     * 2^(2 emin); and the largest magnitude, to size the integers */
    int emin = 2000, top = -2000;
    const double *pts[5] = {z[0], k > 0 ? z[1] : zb, k > 1 ? z[2] : zb, zb, x};
    for (int i = 0; i < 5; i++)
        for (int c = 0; c < 3; c++) {
            if (low_exp_min(pts[i][c], &emin)) return 2;
            if (pts[i][c] != 0) top = ilogb(pts[i][c]) > top ? ilogb(pts[i][c]) : top;
        }
    int ew = 2000;
    for (int i = 0; i < 4; i++) {
        double w = pts[i][3];
        if (low_exp_min(w, &ew)) return 2;
        if (w != 0) top = (ilogb(w) + 1) / 2 + 1 > top ? (ilogb(w) + 1) / 2 + 1 : top;
    }
    if (ew != 2000) emin = emin < (ew >> 1) ? emin : (ew >> 1); /* floor(ew / 2) */
    if (emin == 2000) emin = 0; /* every input zero */
    int et = fl_big_low_exponent(t); /* t = T 2^et, T odd, et <= -1 */
    if (1 - et > 1000) return 2;
    int bits = top + 2 - emin;       /* a coordinate or sqrt(weight) after scaling */
    if (bits > EXACT_MAX_BITS) return 2;
    /* entries: squares of differences (2 bits + 2), + weights, times T (53 bits) or shifted by
     * 1 - et; the determinant of at most 3 x 3 of them */
    int entry = 2 * bits + 8 + 53 + (1 - et);
    int limbs = (3 * entry + 16) / 32 + 4;
    int wl = (1024 - 2 * emin) / 32 + 4;
    if (wl > limbs) limbs = wl;
    arena A = {NULL, limbs, 0, 64};
    A.pool = malloc((size_t)A.cap * (size_t)limbs * sizeof(uint32_t));
    if (!A.pool) return 2;
    fl_big P[5][3], W[4];
    for (int i = 0; i < 5; i++)
        for (int c = 0; c < 3; c++) {
            P[i][c] = take(&A);
            fl_big_set_double(&P[i][c], pts[i][c], emin);
        }
    for (int i = 0; i < 4; i++) {
        W[i] = take(&A);
        fl_big_set_double(&W[i], pts[i][3], 2 * emin);
    }
    /* E[0..k-1] the edges e_i, E[k] = e_b, D = d, all minus z_0 (rows 1, 2 of pts are e_1,
     * e_2 when k says so, row 3 is b, row 4 is x) */
    fl_big E[3][3], D[3];
    int rowof[3] = {1, 2, 3};
    rowof[k] = 3;
    for (int j = 0; j <= k; j++)
        for (int c = 0; c < 3; c++) {
            E[j][c] = take(&A);
            fl_big_sub(&E[j][c], &P[rowof[j]][c], &P[0][c]);
        }
    for (int c = 0; c < 3; c++) {
        D[c] = take(&A);
        fl_big_sub(&D[c], &P[4][c], &P[0][c]);
    }
    /* M: rows j < k [G_j0 .. G_j,k-1, g_j], last row [U_0 .. U_{k-1}, C] scaled by 2^(1-et):
     * 2^(1-et) (t r - e.d) = T (|e|^2 - w + w_0) - 2^(1-et) e.d */
    fl_big M[3][3], T = take(&A), S = take(&A), tmp = take(&A), tmp2 = take(&A);
    fl_big_set_double(&T, ldexp(t, -et), 0);
    fl_big_set_double(&S, ldexp(1, 1 - et), 0);
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++)
            M[i][j] = take(&A);
    for (int i = 0; i < k; i++)
        for (int j = 0; j <= k; j++)
            dot(&A, &M[i][j], E[i], E[j]);
    for (int j = 0; j <= k; j++) {
        int wrow = rowof[j]; /* the weight of e_j's ball */
        dot(&A, &tmp, E[j], E[j]);
        fl_big_sub(&tmp, &tmp, &W[wrow]);
        fl_big_add(&tmp, &tmp, &W[0]);
        fl_big_mul(&M[k][j], &T, &tmp);
        dot(&A, &tmp, E[j], D);
        fl_big_mul(&tmp2, &S, &tmp);
        fl_big_sub(&M[k][j], &M[k][j], &tmp2);
    }
    int sign;
    if (k == 0) {
        sign = fl_big_sign(&M[0][0]);
    } else if (k == 1) {
        fl_big_mul(&tmp, &M[0][0], &M[1][1]);
        fl_big_mul(&tmp2, &M[0][1], &M[1][0]);
        fl_big_sub(&tmp, &tmp, &tmp2);
        sign = fl_big_sign(&tmp);
    } else {
        fl_big m2 = take(&A), acc = take(&A);
        static const int cof[3][2] = {{1, 2}, {0, 2}, {0, 1}};
        for (int j = 0; j < 3; j++) { /* expansion along row 0 */
            int c0 = cof[j][0], c1 = cof[j][1];
            fl_big_mul(&tmp, &M[1][c0], &M[2][c1]);
            fl_big_mul(&tmp2, &M[1][c1], &M[2][c0]);
            fl_big_sub(&m2, &tmp, &tmp2);
            fl_big_mul(&tmp, &M[0][j], &m2);
            if (j == 1)
                fl_big_sub(&acc, &acc, &tmp);
            else
                fl_big_add(&acc, &acc, &tmp);
        }
        sign = fl_big_sign(&acc);
    }
    free(A.pool);
    return sign;
}

/* Exact power-distance predicates of the skin: the link test of the mixed-cell walk
 * (src/skin/skin_cell.c) and the bordered determinants of the dual complex of a union of balls
 * (src/skin/skin_euler.c). Each is a floating-point filter with a rigorous error bound and a
 * big-integer exact stage (fl_big, bigint.c); power.h states what each function returns.
 *
 * The link test. For a simplex X = (z_0 .. z_k), k <= 2, a ball b of its link and a query
 * point x, the walk asks whether v = f + q/t (x - f = p + q, q orthogonal to aff X, f the focus
 * of X) satisfies pi_b(v) >= pi_X(v). With a = z_0, e_i = z_i - a, e_b = z_b - a, d = x - a,
 * the Gram matrix G_ij = e_i.e_j, r_i = (|e_i|^2 - w_i + w_0) / 2 (same for r_b),
 * u_i = t r_i - e_i.d and c = t r_b - e_b.d, the test value the walk computes in floating point
 * is
 *     H = t (pi_b(v) - pi_X(v)) = 2 (c - u^T G^-1 g),   g_i = e_i.e_b,
 * and by the Schur complement det [[G, g], [u^T, c]] = det G (c - u^T G^-1 g), det G > 0. So
 * sign H = sign det M with M that (k+1) x (k+1) matrix of dot products of coordinate
 * differences: a polynomial in the input doubles, evaluated exactly in big integers (the inputs
 * scaled by one power of two into integers, the weights by its square, the last row by the
 * power of two that makes t an odd integer). The walk uses it where the floating-point test is
 * within its rounding band: on the faces of B*'s nearly flat tetrahedra the link test of the
 * fourth ball is almost constant along aff nu_X, so the band covers most of the line
 * (docs/skin.md, "The bunny", round 11).
 *
 * The bordered determinants. With a = z_0, e_i = z_i - a (i < k), G_ij = e_i.e_j (det G > 0
 * for the simplex of a triangulation), s_i = |e_i|^2 - w_i + w_0 (so the focus is
 * f = a + sum eta_i e_i with G eta = s / 2):
 *   - link test of ball b: pi_b(f) - pi_X(f) = s_b - g^T G^-1 s with g_i = e_i.e_b, and by
 *     the Schur complement det [[G, g], [s^T, s_b]] = det G (s_b - s^T G^-1 g): same sign;
 *   - power: pi_X(f) = |f - a|^2 - w_0 = s^T G^-1 s / 4 - w_0, and
 *     det [[G, s], [s^T, 4 w_0]] = det G (4 w_0 - s^T G^-1 s): the opposite sign.
 * Each determinant (at most 4 x 4) is first evaluated in floating point with a forward error
 * bound (fl_power_bordered_filter); when the value is not certified it is evaluated in big
 * integers (fl_power_bordered_exact: the inputs scaled by one power of two into integers). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "predicates/power.h"
#include "predicates/predicates_internal.h"

/* Largest integer length (bits) of an input after scaling that the exact link test accepts;
 * beyond it the caller falls back to the scan (only absurd exponent ranges get there). */
#define EXACT_MAX_BITS 4200

/* Storage for the big integers of one evaluation: 64 slots of `limbs` limbs each. */
typedef struct arena {
    uint32_t *pool;
    int limbs, used;
} arena;

static int arena_init(arena *A, int limbs)
{
    A->limbs = limbs;
    A->used = 0;
    A->pool = malloc((size_t)64 * (size_t)limbs * sizeof(uint32_t));
    return A->pool == NULL;
}

static fl_big take(arena *A)
{
    fl_big r = {A->pool + (size_t)A->used++ * (size_t)A->limbs, 0, 0};
    return r;
}

/* r = u.v over three coordinates; tmp is scratch storage distinct from r, u and v. */
static void big_dot(fl_big *r, fl_big *tmp, const fl_big *u, const fl_big *v)
{
    r->len = 0;
    r->neg = 0;
    for (int c = 0; c < 3; c++) {
        fl_big_mul(tmp, &u[c], &v[c]);
        fl_big_add(r, r, tmp);
    }
}

/* ---- the link test of the mixed-cell walk ---- */

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

/* The sign of the link determinant det M in floating point with a bound on its error
 * (the same matrix with its last row multiplied by the positive 2^et: t (|e_j|^2 - w_j + w_0)
 * - 2 e_j.d), or 0 when the bound does not decide it. Inputs of magnitude 0 or in
 * [2^-100, 2^100] keep every product of the degree-6 determinant far from overflow, and a
 * product's underflow is covered by its absolute term; other inputs are decided exactly. */
int fl_power_link_filter(const double *const *pts, int k, double t)
{
    if (k > 2 || !(t > 0 && t < 1)) return 0;
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

/* The exact stage of the link test: det M in big integers (the inputs scaled by one power of
 * two into integers, the weights by its square, the last row by the power of two that makes t
 * an odd integer). */
int fl_power_link_exact(const double *const *pts, int k, double t)
{
    if (k > 2 || !(t > 0 && t < 1)) return 2;
    /* the common scale: every coordinate an integer multiple of 2^emin, every weight of
     * 2^(2 emin); and the largest magnitude, to size the integers */
    int emin = 2000, top = -2000;
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
    arena A;
    if (arena_init(&A, limbs)) return 2;
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
    fl_big M[3][3], T = take(&A), S = take(&A), tmp = take(&A), tmp2 = take(&A), p = take(&A);
    fl_big_set_double(&T, ldexp(t, -et), 0);
    fl_big_set_double(&S, ldexp(1, 1 - et), 0);
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++)
            M[i][j] = take(&A);
    for (int i = 0; i < k; i++)
        for (int j = 0; j <= k; j++)
            big_dot(&M[i][j], &p, E[i], E[j]);
    for (int j = 0; j <= k; j++) {
        int wrow = rowof[j]; /* the weight of e_j's ball */
        big_dot(&tmp, &p, E[j], E[j]);
        fl_big_sub(&tmp, &tmp, &W[wrow]);
        fl_big_add(&tmp, &tmp, &W[0]);
        fl_big_mul(&M[k][j], &T, &tmp);
        big_dot(&tmp, &p, E[j], D);
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

/* ---- the bordered determinants of the dual complex ---- */

/* The 24 permutations of 0..3 and their signs (Leibniz expansion of a determinant). A
 * determinant of order m < 4 uses the ones that fix m..3, whose signs are those of their
 * restriction to 0..m-1. */
static const unsigned char perm4[24][4] = {
    {0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {0, 3, 2, 1},
    {1, 0, 2, 3}, {1, 0, 3, 2}, {1, 2, 0, 3}, {1, 2, 3, 0}, {1, 3, 0, 2}, {1, 3, 2, 0},
    {2, 0, 1, 3}, {2, 0, 3, 1}, {2, 1, 0, 3}, {2, 1, 3, 0}, {2, 3, 0, 1}, {2, 3, 1, 0},
    {3, 0, 1, 2}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 1, 2, 0}, {3, 2, 0, 1}, {3, 2, 1, 0}};
static const signed char perm4_sign[24] = {1, -1, -1, 1, 1, -1, -1, 1, 1, -1, -1, 1,
                                           1, -1, -1, 1, 1, -1, -1, 1, 1, -1, -1, 1};

static int perm_fixes_tail(int q, int m)
{
    for (int i = m; i < 4; i++)
        if (perm4[q][i] != i) return 0;
    return 1;
}

/* ---- the bordered determinant in floating point, certified or not ---- */

static int in_filter_range(double v)
{
    double a = fabs(v);
    return a == 0 || (a >= 1e-30 && a <= 1e30);
}

/* Sign of the bordered determinant of simplex z[0..k] (mode FL_BORDERED_LINK with ball z[k+1],
 * or FL_BORDERED_POWER) when floating point certifies it, else 2. Error bound: every entry is a
 * sum of at most 5 products or differences of input values, computed with relative error <= 8u
 * of the sum of the absolute values of its terms, A_ij (u = 2^-53; the differences e_i carry u
 * each). A
 * Leibniz term of m <= 4 entries then errs by <= ((1 + 8u)^4 (1 + u)^3 - 1) prod A <= 36u
 * prod A, and the sum of at most 24 terms adds <= 24u (1 + 36u) sum prod A. So
 * |D_float - D| <= 61u P with P = sum over permutations of prod A; the filter asks for
 * |D_float| > 1e-13 P (about 15 times that bound, which also covers the rounding of P). The
 * bound assumes no underflow or overflow: every nonzero |e_ic| and sqrt|w| must lie in
 * [1e-30, 1e30], so every product of up to 8 of them stays within [1e-240, 1e240]; other
 * inputs go to the exact stage. */
int fl_power_bordered_filter(const double *const *z, int k, int mode)
{
    const double *z0 = z[0];
    double e[4][3], m[4][4], a[4][4];
    int rows = k + (mode == FL_BORDERED_LINK);
    for (int i = 0; i < rows; i++) {
        const double *zi = z[i + 1];
        for (int c = 0; c < 3; c++) {
            e[i][c] = zi[c] - z0[c];
            if (!in_filter_range(e[i][c])) return 2;
        }
        if (!in_filter_range(sqrt(fabs(zi[3])))) return 2;
    }
    if (!in_filter_range(sqrt(fabs(z0[3])))) return 2;
    /* s_i and its magnitude, for the k edges and (FL_BORDERED_LINK) the ball b in row k */
    double s[4], sa[4];
    for (int i = 0; i < rows; i++) {
        const double *zi = z[i + 1];
        double ee = e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2];
        s[i] = ee - zi[3] + z0[3];
        sa[i] = ee + fabs(zi[3]) + fabs(z0[3]);
    }
    for (int i = 0; i < k; i++) {
        for (int j = 0; j < k; j++) {
            m[i][j] = e[i][0] * e[j][0] + e[i][1] * e[j][1] + e[i][2] * e[j][2];
            a[i][j] = fabs(e[i][0] * e[j][0]) + fabs(e[i][1] * e[j][1]) + fabs(e[i][2] * e[j][2]);
        }
        if (mode == FL_BORDERED_LINK) {
            m[i][k] = e[i][0] * e[k][0] + e[i][1] * e[k][1] + e[i][2] * e[k][2];
            a[i][k] = fabs(e[i][0] * e[k][0]) + fabs(e[i][1] * e[k][1]) + fabs(e[i][2] * e[k][2]);
        } else {
            m[i][k] = s[i];
            a[i][k] = sa[i];
        }
        m[k][i] = s[i];
        a[k][i] = sa[i];
    }
    if (mode == FL_BORDERED_LINK) {
        m[k][k] = s[k];
        a[k][k] = sa[k];
    } else {
        m[k][k] = 4 * z0[3];
        a[k][k] = fabs(m[k][k]);
    }
    double d = 0, p = 0;
    for (int q = 0; q < 24; q++) {
        if (!perm_fixes_tail(q, k + 1)) continue;
        double prod = perm4_sign[q], mag = 1;
        for (int i = 0; i <= k; i++) {
            prod *= m[i][perm4[q][i]];
            mag *= a[i][perm4[q][i]];
        }
        d += prod;
        p += mag;
    }
    if (!isfinite(d) || !isfinite(p)) return 2;
    if (fabs(d) > 1e-13 * p) return d > 0 ? 1 : -1;
    if (p == 0) return 0; /* every entry and term is exactly zero */
    return 2;
}

/* ---- the bordered determinant in big integers ---- */

/* Exact sign of the same determinant, or 2 when out of memory or an input is not finite.
 * Every coordinate is an integer multiple of 2^emin and every weight of 2^(2 emin) (emin the
 * smallest lowest-set-bit exponent, halved for the weights), so scaling them by 2^-emin and
 * 2^-2emin makes every entry an integer and multiplies the determinant by a positive power of
 * two. Sizes: a scaled coordinate or square root of a weight has at most `bits` bits; a
 * difference bits + 1, an entry 2 bits + 6 (three products and two weights), a Leibniz term of
 * four entries 8 bits + 24, the sum of 24 terms 5 more. */
int fl_power_bordered_exact(const double *const *z, int k, int mode)
{
    int nb = k + 1 + (mode == FL_BORDERED_LINK);
    int emin = 4000, ew = 4000, top = -4000;
    for (int i = 0; i < nb; i++)
        for (int c = 0; c < 4; c++)
            if (!isfinite(z[i][c])) return 2;
    for (int i = 0; i < nb; i++) {
        for (int c = 0; c < 3; c++)
            if (z[i][c] != 0) {
                int lo = fl_big_low_exponent(z[i][c]);
                emin = lo < emin ? lo : emin;
                top = ilogb(z[i][c]) > top ? ilogb(z[i][c]) : top;
            }
        double w = z[i][3];
        if (w != 0) {
            int lo = fl_big_low_exponent(w);
            ew = lo < ew ? lo : ew;
            int half = (ilogb(w) + 1) / 2 + 1;
            top = half > top ? half : top;
        }
    }
    if (ew != 4000) {
        int half = ew >= 0 ? ew / 2 : -((-ew + 1) / 2); /* floor(ew / 2) */
        emin = half < emin ? half : emin;
    }
    if (emin == 4000) emin = 0; /* every input zero */
    if (top == -4000) top = 0;
    int bits = top + 2 - emin;
    int limbs = (8 * bits + 64) / 32 + 4;
    int need_in = (1024 - 2 * emin) / 32 + 4;
    if (need_in > limbs) limbs = need_in;
    arena A;
    if (arena_init(&A, limbs)) return 2;
    fl_big P[5][3], W[5], E[4][3], S[4], M[4][4];
    for (int i = 0; i < nb; i++) {
        for (int c = 0; c < 3; c++) {
            P[i][c] = take(&A);
            fl_big_set_double(&P[i][c], z[i][c], emin);
        }
        W[i] = take(&A);
        fl_big_set_double(&W[i], z[i][3], 2 * emin);
    }
    fl_big tmp = take(&A), tmp2 = take(&A), acc = take(&A);
    int rows = nb - 1; /* e_1 .. e_k and, for FL_BORDERED_LINK, e_b */
    for (int i = 0; i < rows; i++) {
        for (int c = 0; c < 3; c++) {
            E[i][c] = take(&A);
            fl_big_sub(&E[i][c], &P[i + 1][c], &P[0][c]);
        }
        S[i] = take(&A);
        big_dot(&S[i], &tmp, E[i], E[i]);
        fl_big_sub(&S[i], &S[i], &W[i + 1]);
        fl_big_add(&S[i], &S[i], &W[0]);
    }
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++)
            M[i][j] = take(&A);
    for (int i = 0; i < k; i++) {
        for (int j = 0; j < k; j++)
            big_dot(&M[i][j], &tmp, E[i], E[j]);
        if (mode == FL_BORDERED_LINK)
            big_dot(&M[i][k], &tmp, E[i], E[k]);
        else
            fl_big_add(&M[i][k], &S[i], &M[i][k]); /* M[i][k] starts at zero */
        fl_big_add(&M[k][i], &S[i], &M[k][i]);
    }
    if (mode == FL_BORDERED_LINK) {
        fl_big_add(&M[k][k], &S[k], &M[k][k]);
    } else {
        fl_big_add(&M[k][k], &W[0], &W[0]);
        fl_big_add(&M[k][k], &M[k][k], &M[k][k]);
    }
    fl_big zero = take(&A);
    for (int q = 0; q < 24; q++) {
        if (!perm_fixes_tail(q, k + 1)) continue;
        fl_big_add(&tmp, &M[0][perm4[q][0]], &zero);
        for (int i = 1; i <= k; i++) { /* tmp2 = tmp * entry, then swap the two slots */
            fl_big_mul(&tmp2, &tmp, &M[i][perm4[q][i]]);
            fl_big swap = tmp;
            tmp = tmp2;
            tmp2 = swap;
        }
        if (perm4_sign[q] > 0)
            fl_big_add(&acc, &acc, &tmp);
        else
            fl_big_sub(&acc, &acc, &tmp);
    }
    int sign = fl_big_sign(&acc);
    free(A.pool);
    return sign;
}

int fl_power_bordered_sign(const double *const *z, int k, int mode)
{
    int s = fl_power_bordered_filter(z, k, mode);
    return s != 2 ? s : fl_power_bordered_exact(z, k, mode);
}

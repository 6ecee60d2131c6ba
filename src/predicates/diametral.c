/* Exact signs of sums of products of coordinate differences (dot_sum.h), and the
 * diametral-ball test built on them: the sign of (p - a).(p - b), negative exactly when p lies
 * inside the ball with diameter ab (Thales). */
#include <math.h>

#include "flintstone.h"
#include "predicates/dot_sum.h"
#include "predicates/predicates_internal.h"

enum {
    COORD_LIMBS = 68,                      /* a double scaled to an integer: see exact.c */
    DIFF_LIMBS = COORD_LIMBS + 1,          /* one carry more */
    PROD_LIMBS = 2 * DIFF_LIMBS,           /* a product of two differences */
    TERM_LIMBS = PROD_LIMBS + COORD_LIMBS, /* times a scaled coefficient */
    SUM_LIMBS = TERM_LIMBS + 4             /* up to 12 such terms summed */
};

/* Lowers *emin to the exponent of the lowest set bit among v[0..count-1] (zeros have none);
 * *any records whether some value was nonzero. */
static void low_exponent(const double *v, int count, int *emin, int *any)
{
    for (int i = 0; i < count; i++)
        if (v[i] != 0) {
            int e = fl_big_low_exponent(v[i]);
            if (!*any || e < *emin) *emin = e;
            *any = 1;
        }
}

/* Points are scaled by 2^-ep and coefficients by 2^-ec into integers; every term then carries
 * the same factor 2^(2 ep + ec) > 0, so the integer sum has the sign of the true sum. */
/* The floating filter: each term coef (x-y)(u-w) is off by at most four roundings (two
 * differences, two products), and summing at most 12 terms adds 11 more, so 16u times the sum
 * of the terms' magnitudes bounds the error (u = 2^-53, second-order terms absorbed by the
 * slack). Valid while no factor is beyond 2^300 or below 2^-300 in magnitude (no overflow, no
 * subnormal product); otherwise, or when undecided, it returns 2. */
static int filtered_sign(int terms, const double *coef, const double *const *x,
                         const double *const *y, const double *const *u, const double *const *w,
                         int dim)
{
    double sum = 0, mag = 0;
    for (int k = 0; k < terms; k++)
        for (int i = 0; i < dim; i++) {
            double d1 = x[k][i] - y[k][i], d2 = u[k][i] - w[k][i];
            double f[3] = {fabs(d1), fabs(d2), fabs(coef[k])};
            for (int j = 0; j < 3; j++)
                if (f[j] != 0 && (f[j] > 0x1p300 || f[j] < 0x1p-300)) return 2;
            double t = coef[k] * (d1 * d2);
            sum += t;
            mag += fabs(t);
        }
    double bound = 16.0 * 0x1p-53 * mag;
    return sum > bound ? 1 : sum < -bound ? -1 : 2;
}

int fl_dot_sum_sign(int terms, const double *coef, const double *const *x, const double *const *y,
                    const double *const *u, const double *const *w, int dim)
{
    if (terms < 1 || terms > FL_DOT_SUM_MAX_TERMS || (dim != 2 && dim != 3)) return 0;
    int fast = filtered_sign(terms, coef, x, y, u, w, dim);
    if (fast != 2) return fast;
    int ep = 0, ec = 0, any_point = 0, any_coef = 0;
    for (int k = 0; k < terms; k++) {
        low_exponent(x[k], dim, &ep, &any_point);
        low_exponent(y[k], dim, &ep, &any_point);
        low_exponent(u[k], dim, &ep, &any_point);
        low_exponent(w[k], dim, &ep, &any_point);
    }
    low_exponent(coef, terms, &ec, &any_coef);
    if (!any_point || !any_coef) return 0;
    uint32_t l1[COORD_LIMBS], l2[COORD_LIMBS], ld1[DIFF_LIMBS], ld2[DIFF_LIMBS], lc[COORD_LIMBS];
    uint32_t lp[PROD_LIMBS], lt[TERM_LIMBS], ls[SUM_LIMBS];
    fl_big A = {l1, 0, 0}, B = {l2, 0, 0}, D1 = {ld1, 0, 0}, D2 = {ld2, 0, 0}, C = {lc, 0, 0};
    fl_big P = {lp, 0, 0}, T = {lt, 0, 0}, S = {ls, 0, 0};
    for (int k = 0; k < terms; k++) {
        fl_big_set_double(&C, coef[k], ec);
        for (int i = 0; i < dim; i++) {
            fl_big_set_double(&A, x[k][i], ep);
            fl_big_set_double(&B, y[k][i], ep);
            fl_big_sub(&D1, &A, &B);
            fl_big_set_double(&A, u[k][i], ep);
            fl_big_set_double(&B, w[k][i], ep);
            fl_big_sub(&D2, &A, &B);
            fl_big_mul(&P, &D1, &D2);
            fl_big_mul(&T, &P, &C);
            fl_big_add(&S, &S, &T);
        }
    }
    return fl_big_sign(&S);
}

int fl_diametral(const double *a, const double *b, const double *p, int dim)
{
    if (dim != 2 && dim != 3) return 0;
    double d = 0, mag = 0, big = 0, small = INFINITY;
    for (int k = 0; k < dim; k++) {
        double u = p[k] - a[k], v = p[k] - b[k];
        d += u * v;
        mag += fabs(u * v);
        double m = fmax(fabs(u), fabs(v));
        big = fmax(big, m);
        if (m > 0) small = fmin(small, m);
    }
    /* Each difference and product is off by at most one rounding (relative u = 2^-53), and the
     * sum of at most three terms adds two more; (1+u)^5 - 1 < 6u bounds the total relative to
     * the sum of magnitudes. The range test keeps products clear of overflow and of the
     * subnormal range, where the relative bound would fail. */
    if (big < 0x1p480 && small > 0x1p-480) {
        double bound = 6.0 * 0x1p-53 * mag;
        if (d > bound) return 1;
        if (d < -bound) return -1;
    }
    const double one = 1, *x[1] = {p}, *y[1] = {a}, *w[1] = {b};
    return fl_dot_sum_sign(1, &one, x, y, x, w, dim);
}

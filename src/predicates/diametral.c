/* The diametral-ball test: the sign of (p - a).(p - b), negative exactly when p lies inside
 * the ball with diameter ab (Thales). Gabriel edges, the two-point case of the smallest
 * enclosing disc and distance-ordered graphs decide with it. */
#include <math.h>

#include "flintstone.h"
#include "predicates/predicates_internal.h"

enum {
    COORD_LIMBS = 68,             /* a double scaled to an integer: see exact.c */
    DIFF_LIMBS = COORD_LIMBS + 1, /* one carry more */
    PROD_LIMBS = 2 * DIFF_LIMBS,  /* a product of two differences */
    SUM_LIMBS = PROD_LIMBS + 2    /* three products summed */
};

/* All coordinates are multiples of 2^emin; scaled by 2^-emin they are integers, and the sum of
 * products of integer differences is exact, with the sign of the unscaled value. */
static int exact_sign(const double *a, const double *b, const double *p, int dim)
{
    int emin = 0, any = 0;
    const double *pts[3] = {a, b, p};
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < dim; k++)
            if (pts[i][k] != 0) {
                int e = fl_big_low_exponent(pts[i][k]);
                if (!any || e < emin) emin = e;
                any = 1;
            }
    uint32_t xa[COORD_LIMBS], xb[COORD_LIMBS], xp[COORD_LIMBS], du[DIFF_LIMBS], dv[DIFF_LIMBS];
    uint32_t pr[PROD_LIMBS], sum[SUM_LIMBS];
    fl_big A = {xa, 0, 0}, B = {xb, 0, 0}, P = {xp, 0, 0}, U = {du, 0, 0}, V = {dv, 0, 0};
    fl_big R = {pr, 0, 0}, S = {sum, 0, 0};
    for (int k = 0; k < dim; k++) {
        fl_big_set_double(&A, a[k], emin);
        fl_big_set_double(&B, b[k], emin);
        fl_big_set_double(&P, p[k], emin);
        fl_big_sub(&U, &P, &A);
        fl_big_sub(&V, &P, &B);
        fl_big_mul(&R, &U, &V);
        fl_big_add(&S, &S, &R);
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
    return exact_sign(a, b, p, dim);
}

/* Internal interface of the predicates module: the exact integer arithmetic behind the exact
 * stage of every predicate. Not part of the public API. */
#ifndef FL_PREDICATES_INTERNAL_H
#define FL_PREDICATES_INTERNAL_H

#include <stdint.h>

/* A signed integer in sign-magnitude form over caller-provided storage: |value| is
 * sum limb[i] * 2^(32 i) for i < len, limb[len-1] != 0, and len == 0 means zero (neg == 0).
 * The caller sizes `limb` for the largest value the computation can reach (see exact.c). */
typedef struct fl_big {
    uint32_t *limb;
    int len;
    int neg;
} fl_big;

/* Exponent of the lowest set bit of a finite nonzero double: x = odd * 2^result. */
int fl_big_low_exponent(double x);

/* r = x * 2^(-emin) for a finite double x whose lowest set bit is at exponent >= emin, so the
 * result is an integer. r needs ceil((1024 - emin) / 32) + 2 limbs. */
void fl_big_set_double(fl_big *r, double x, int emin);

/* r = a + b and r = a - b. r may share storage with a or b (limbs are read before written). */
void fl_big_add(fl_big *r, const fl_big *a, const fl_big *b);
void fl_big_sub(fl_big *r, const fl_big *a, const fl_big *b);

/* r = a * b; r must not share storage with a or b and needs a.len + b.len limbs. */
void fl_big_mul(fl_big *r, const fl_big *a, const fl_big *b);

static inline int fl_big_sign(const fl_big *a)
{
    return a->len == 0 ? 0 : (a->neg ? -1 : 1);
}

/* Exact sign of the determinant of a predicate, evaluated in integer arithmetic; every finite
 * input is handled (no overflow or underflow is possible, see exact.c).
 *  - pts[0..n-1] are the points, `dim` (2 or 3) coordinates each; when `weighted`, the weight
 *    follows the coordinates (pts[i][dim]).
 *  - lifted == 0: n == dim + 1, the sign of det[p_i - p_last] (orient2d / orient3d).
 *  - lifted == 1: n == dim + 2, the sign of det[p_i - p_last, |p_i - p_last|^2 - (w_i - w_last)]
 *    (incircle / insphere and their weighted versions; weights are 0 when !weighted). */
int fl_exact_det_sign(const double *const *pts, int n, int dim, int lifted, int weighted);

#endif /* FL_PREDICATES_INTERNAL_H */

/* The exact stage: a predicate's determinant evaluated in integer arithmetic.
 *
 * Why integers and not floating-point expansions: every finite double is m * 2^e with an
 * integer m < 2^53 and -1074 <= e <= 971. Scaling all inputs of one call by the same power of
 * two 2^-emin (emin = the lowest set bit among them) turns every coordinate into an integer
 * and multiplies the determinant, a homogeneous polynomial, by a positive factor: the sign is
 * unchanged. Integer arithmetic then cannot overflow or underflow for any finite input, which
 * double-based expansions cannot promise when products of tiny numbers fall below 2^-1074 or
 * sums of huge ones exceed 2^1024. Weights count as squared lengths (they are subtracted from
 * |p|^2), so they are scaled by 2^(-2 emin) and emin is lowered until that is an integer too.
 *
 * Sizes (bits of the integers, for the worst finite input):
 *   coordinate and its difference  < 2^2099 (1024 + 1074 + 1)        -> COORD_LIMBS
 *   weight and its difference      < 2^3173 (1024 + 2 * 1074 + 1)    -> WEIGHT_LIMBS
 *   lift |d|^2 - dw                < 2^4201                          -> LIFT_LIMBS
 *   k x k coordinate minor         < k! * 2^(2099 k)
 *   final lifted minor             < 4! * 2^(3 * 2099 + 4201) ~ 2^10502 -> MINOR3_LIMBS
 * fl_big_mul writes a.len + b.len limbs before trimming, so each capacity below covers the
 * untrimmed product of its operands' largest lengths. */
#include <limits.h>
#include <math.h>

#include "predicates/predicates_internal.h"

enum {
    COORD_LIMBS = 68,   /* 66 for 2099 bits, +2 for fl_big_set_double's slack */
    WEIGHT_LIMBS = 104, /* 100 for 3173 bits, +2 slack, rounded */
    LIFT_LIMBS = 136,   /* 132 = 2 * 66 (square of a difference) */
    MINOR1_LIMBS = 136, /* 2 x 2 coordinate minors: 66 + 66 */
    MINOR2_LIMBS = 272, /* 3 x 3: 66 + 132 (orient3d) or 132 + 132 (incircle, lift column) */
    MINOR3_LIMBS = 336  /* 4 x 4 with lift column (insphere): 132 + 197 */
};

/* NaN and infinities have no exact value; the contract leaves their sign unspecified and this
 * keeps the integer code well-defined for them. */
static double finite_or_zero(double x)
{
    return isfinite(x) ? x : 0;
}

static int floor_half(int e)
{
    return e >= 0 ? e / 2 : -((-e + 1) / 2);
}

/* The common scale: every coordinate is an integer multiple of 2^emin and every weight of
 * 2^(2 emin). */
static int common_low_exponent(const double *const *pts, int n, int dim, int weighted)
{
    int emin = INT_MAX;
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < dim; j++) {
            double x = finite_or_zero(pts[i][j]);
            if (x == 0) continue;
            int e = fl_big_low_exponent(x);
            if (e < emin) emin = e;
        }
        double w = weighted ? finite_or_zero(pts[i][dim]) : 0;
        if (w != 0) {
            int e = floor_half(fl_big_low_exponent(w));
            if (e < emin) emin = e;
        }
    }
    return emin == INT_MAX ? 0 : emin;
}

typedef struct exact_matrix {
    int n; /* rows = columns */
    fl_big ent[4][4];
    uint32_t coord_st[4][3][COORD_LIMBS];
    uint32_t lift_st[4][LIFT_LIMBS];
} exact_matrix;

/* Row i = (p_i - p_last) and, when lifted, |p_i - p_last|^2 - (w_i - w_last). */
static void build_rows(exact_matrix *m, const double *const *pts, int n, int dim, int lifted,
                       int weighted)
{
    int emin = common_low_exponent(pts, n, dim, weighted);
    uint32_t base_st[3][COORD_LIMBS], sq_st[LIFT_LIMBS], w_st[2][WEIGHT_LIMBS];
    fl_big base[3], sq = {sq_st, 0, 0}, w = {w_st[0], 0, 0}, wlast = {w_st[1], 0, 0};
    const double *last = pts[n - 1];
    for (int j = 0; j < dim; j++) {
        base[j].limb = base_st[j];
        fl_big_set_double(&base[j], finite_or_zero(last[j]), emin);
    }
    m->n = n - 1;
    for (int i = 0; i + 1 < n; i++) {
        for (int j = 0; j < dim; j++) {
            fl_big *e = &m->ent[i][j];
            e->limb = m->coord_st[i][j];
            fl_big_set_double(e, finite_or_zero(pts[i][j]), emin);
            fl_big_sub(e, e, &base[j]);
        }
        if (!lifted) continue;
        fl_big *l = &m->ent[i][dim];
        l->limb = m->lift_st[i];
        l->len = 0;
        l->neg = 0;
        for (int j = 0; j < dim; j++) {
            fl_big_mul(&sq, &m->ent[i][j], &m->ent[i][j]);
            fl_big_add(l, l, &sq);
        }
        if (weighted) {
            fl_big_set_double(&w, finite_or_zero(pts[i][dim]), 2 * emin);
            fl_big_set_double(&wlast, finite_or_zero(last[dim]), 2 * emin);
            fl_big_sub(&w, &w, &wlast);
            fl_big_sub(l, l, &w);
        }
    }
}

static int popcount4(int mask)
{
    return (mask & 1) + (mask >> 1 & 1) + (mask >> 2 & 1) + (mask >> 3 & 1);
}

/* Sign of det(ent) by expanding column after column: the minors of columns 0..k over every
 * (k+1)-subset of rows come from the minors of columns 0..k-1 (Laplace along column k), so
 * each 2 x 2 and 3 x 3 minor is computed once (28 products for 4 x 4). */
static int det_sign_by_minors(const exact_matrix *m)
{
    static const int level_cap[4] = {0, MINOR1_LIMBS, MINOR2_LIMBS, MINOR3_LIMBS};
    uint32_t pool1[6][MINOR1_LIMBS], pool2[4][MINOR2_LIMBS], pool3[1][MINOR3_LIMBS];
    uint32_t tmp_st[MINOR3_LIMBS];
    uint32_t *pools[4] = {0, pool1[0], pool2[0], pool3[0]};
    fl_big minor[16], tmp = {tmp_st, 0, 0};
    int n = m->n, used[4] = {0, 0, 0, 0}, full = (1 << n) - 1;
    for (int i = 0; i < n; i++)
        minor[1 << i] = m->ent[i][0];
    for (int k = 1; k < n; k++) {
        for (int mask = 1; mask <= full; mask++) {
            if (popcount4(mask) != k + 1) continue;
            fl_big *acc = &minor[mask];
            acc->limb = pools[k] + (used[k]++) * level_cap[k];
            acc->len = 0;
            acc->neg = 0;
            int pos = 0;
            for (int i = 0; i < n; i++) {
                if (!(mask >> i & 1)) continue;
                fl_big_mul(&tmp, &m->ent[i][k], &minor[mask ^ (1 << i)]);
                if ((pos + k) & 1)
                    fl_big_sub(acc, acc, &tmp);
                else
                    fl_big_add(acc, acc, &tmp);
                pos++;
            }
        }
    }
    return fl_big_sign(&minor[full]);
}

int fl_exact_det_sign(const double *const *pts, int n, int dim, int lifted, int weighted)
{
    exact_matrix m;
    build_rows(&m, pts, n, dim, lifted, weighted);
    return det_sign_by_minors(&m);
}

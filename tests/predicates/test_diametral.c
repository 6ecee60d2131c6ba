/* fl_diametral against exact rational evaluation (GMP; mpq_set_d is exact) of (p-a).(p-b). */
#include <gmp.h>

#include "fl_test.h"
#include "predicates/dot_sum.h"

static int oracle(const double *a, const double *b, const double *p, int dim)
{
    mpq_t s, u, v, t;
    mpq_inits(s, u, v, t, NULL);
    for (int k = 0; k < dim; k++) {
        mpq_set_d(u, p[k]);
        mpq_set_d(t, a[k]);
        mpq_sub(u, u, t);
        mpq_set_d(v, p[k]);
        mpq_set_d(t, b[k]);
        mpq_sub(v, v, t);
        mpq_mul(u, u, v);
        mpq_add(s, s, u);
    }
    int sign = mpq_sgn(s);
    mpq_clears(s, u, v, t, NULL);
    return sign;
}

static unsigned long long rng = 20261123;

/* A coordinate drawn from one of several regimes: plain, a coarse grid (many exact zeros of
 * the sum), a grid plus 1 ulp, and extreme magnitudes. */
static double coord(int regime)
{
    double x = fl_test_rand01(&rng) * 2 - 1;
    switch (regime) {
    case 1:
        return (double)(long)(x * 4);
    case 2:
        return nextafter((double)(long)(x * 4), 10);
    case 3:
        return x * 0x1p900;
    case 4:
        return x * 0x1p-1000;
    case 5:
        return ldexp(x, (int)(fl_test_rand_u64(&rng) % 2000) - 1000);
    default:
        return x;
    }
}

static void test_diametral_matches_exact_rationals_in_every_regime(void)
{
    int mismatches = 0, zeros = 0, cases = 0;
    for (int regime = 0; regime < 6; regime++)
        for (int dim = 2; dim <= 3; dim++)
            for (int i = 0; i < 4000; i++) {
                double a[3], b[3], p[3];
                for (int k = 0; k < 3; k++) {
                    a[k] = coord(regime);
                    b[k] = coord(regime);
                    p[k] = coord(regime);
                }
                int want = oracle(a, b, p, dim);
                zeros += want == 0;
                mismatches += fl_diametral(a, b, p, dim) != want;
                cases++;
            }
    CHECK_EQ_INT(mismatches, 0);
    CHECK(zeros > 100); /* the grid regimes do reach the exact stage with true zeros */
    CHECK_EQ_INT(cases, 48000);
}

/* sum_k coef_k (x_k - y_k).(u_k - w_k) in exact rationals. */
static int dot_sum_oracle(int terms, const double *coef, const double *const *x,
                          const double *const *y, const double *const *u, const double *const *w,
                          int dim)
{
    mpq_t s, d1, d2, t;
    mpq_inits(s, d1, d2, t, NULL);
    for (int k = 0; k < terms; k++)
        for (int i = 0; i < dim; i++) {
            mpq_set_d(d1, x[k][i]);
            mpq_set_d(t, y[k][i]);
            mpq_sub(d1, d1, t);
            mpq_set_d(d2, u[k][i]);
            mpq_set_d(t, w[k][i]);
            mpq_sub(d2, d2, t);
            mpq_mul(d1, d1, d2);
            mpq_set_d(t, coef[k]);
            mpq_mul(d1, d1, t);
            mpq_add(s, s, d1);
        }
    int sign = mpq_sgn(s);
    mpq_clears(s, d1, d2, t, NULL);
    return sign;
}

/* Distance comparisons |a-b|^2 - |c-d|^2 and lune tests |p-a|^2 - 2k (p-a).(b-a) with
 * arbitrary (non-integer, tiny, huge) coefficients, as the γ-graph module uses them. */
static void test_dot_sum_sign_matches_exact_rationals(void)
{
    int mismatches = 0, zeros = 0;
    for (int regime = 0; regime < 6; regime++)
        for (int i = 0; i < 3000; i++) {
            int dim = 2 + (i & 1), terms = 1 + (int)(fl_test_rand_u64(&rng) % 4);
            double pts[16][3], coef[4];
            const double *x[4], *y[4], *u[4], *w[4];
            for (int j = 0; j < 16; j++)
                for (int k = 0; k < 3; k++)
                    pts[j][k] = coord(regime);
            for (int k = 0; k < terms; k++) {
                /* Reusing points makes exact cancellations (true zeros) common. */
                x[k] = pts[(4 * k) % 5];
                y[k] = pts[(4 * k + 1) % 5];
                u[k] = pts[(4 * k + 2) % 5];
                w[k] = pts[(4 * k + 3) % 5];
                coef[k] = k == 0 ? 1 : (i % 3 == 0 ? -1 : coord(regime == 3 ? 0 : regime));
            }
            int want = dot_sum_oracle(terms, coef, x, y, u, w, dim);
            zeros += want == 0;
            mismatches += fl_dot_sum_sign(terms, coef, x, y, u, w, dim) != want;
        }
    CHECK_EQ_INT(mismatches, 0);
    CHECK(zeros > 50);
}

static void test_diametral_thales_points_are_on_the_sphere(void)
{
    /* (±3, ±4)/5 on the unit circle with diameter (-1,0)-(1,0): exactly 0 (Thales). */
    const double a[2] = {-1, 0}, b[2] = {1, 0};
    const double on[4][2] = {{0.6, 0.8}, {-0.6, 0.8}, {0, 1}, {0, -1}};
    for (int i = 2; i < 4; i++)
        CHECK_EQ_INT(fl_diametral(a, b, on[i], 2), 0);
    /* 0.6 and 0.8 are not exact in binary: the true sign decides, and the oracle agrees. */
    for (int i = 0; i < 2; i++)
        CHECK_EQ_INT(fl_diametral(a, b, on[i], 2), oracle(a, b, on[i], 2));
    const double in[2] = {0.1, 0.1}, out[2] = {1, 1};
    CHECK_EQ_INT(fl_diametral(a, b, in, 2), -1);
    CHECK_EQ_INT(fl_diametral(a, b, out, 2), 1);
    const double a3[3] = {0, 0, 0}, b3[3] = {2, 2, 2}, c3[3] = {2, 0, 0};
    CHECK_EQ_INT(fl_diametral(a3, b3, c3, 3), 0); /* right angle at c3 */
    CHECK_EQ_INT(fl_diametral(a3, b3, c3, 4), 0); /* unsupported dim */
}

FL_TEST_MAIN(FL_TEST_CASE(test_diametral_matches_exact_rationals_in_every_regime),
             FL_TEST_CASE(test_dot_sum_sign_matches_exact_rationals),
             FL_TEST_CASE(test_diametral_thales_points_are_on_the_sphere))

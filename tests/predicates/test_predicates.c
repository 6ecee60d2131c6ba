/* The plain predicates against an independent exact evaluation (GMP rationals on the full
 * lifted matrices, see oracle.h), on random, near-degenerate, exactly degenerate and
 * extreme-magnitude inputs, plus the documented sign conventions on known configurations. */
#include <float.h>
#include <math.h>
#include <stdint.h>

#include "fl_test.h"
#include "predicates/oracle.h"

typedef struct kind {
    const char *name;
    int dim, lifted, weighted;
} kind;

enum { O2, O3, IC, IS, ICW, ISW, KINDS };
static const kind kinds[KINDS] = {
    {"orient2d", 2, 0, 0}, {"orient3d", 3, 0, 0},          {"incircle", 2, 1, 0},
    {"insphere", 3, 1, 0}, {"incircle_weighted", 2, 1, 1}, {"insphere_weighted", 3, 1, 1},
};

static int npoints(int k)
{
    return kinds[k].dim + 1 + kinds[k].lifted;
}

static int call(int k, double p[5][4])
{
    switch (k) {
    case O2:
        return fl_orient2d(p[0], p[1], p[2]);
    case O3:
        return fl_orient3d(p[0], p[1], p[2], p[3]);
    case IC:
        return fl_incircle(p[0], p[1], p[2], p[3]);
    case IS:
        return fl_insphere(p[0], p[1], p[2], p[3], p[4]);
    case ICW:
        return fl_incircle_weighted(p[0], p[1], p[2], p[3]);
    default:
        return fl_insphere_weighted(p[0], p[1], p[2], p[3], p[4]);
    }
}

static int oracle(int k, double p[5][4])
{
    const double *q[5] = {p[0], p[1], p[2], p[3], p[4]};
    return oracle_sign(q, kinds[k].dim, kinds[k].lifted, kinds[k].weighted);
}

typedef struct tally {
    long cases, mismatches, zeros, positives;
} tally;

/* Compares one case and reports the first few mismatches with exact hex coordinates. */
static void compare(int k, double p[5][4], tally *t)
{
    int got = call(k, p), want = oracle(k, p);
    t->cases++;
    t->zeros += want == 0;
    t->positives += want > 0;
    if (got == want) return;
    if (t->mismatches++ < 5) {
        fprintf(stderr, "%s: got %d, exact %d for", kinds[k].name, got, want);
        for (int i = 0; i < npoints(k); i++) {
            fprintf(stderr, " (");
            for (int j = 0; j < kinds[k].dim + kinds[k].weighted; j++)
                fprintf(stderr, "%s%a", j ? " " : "", p[i][j]);
            fprintf(stderr, ")");
        }
        fprintf(stderr, "\n");
    }
}

static double uniform(unsigned long long *s, double lo, double hi)
{
    return lo + (hi - lo) * fl_test_rand01(s);
}

static int rand_int(unsigned long long *s, int lo, int hi)
{
    return lo + (int)(fl_test_rand_u64(s) % (unsigned long long)(hi - lo + 1));
}

/* Moves x by -1, 0 or +1 ulp. */
static double ulp_noise(unsigned long long *s, double x)
{
    int r = rand_int(s, -1, 1);
    return r == 0 ? x : nextafter(x, r > 0 ? INFINITY : -INFINITY);
}

/* The weight that puts p's lifted point exactly on the plane lift = alpha.x + gamma (small
 * integers alpha, gamma, so it is exact for small integer p): an exactly degenerate power test. */
static double plane_weight(const double *p, int dim, const int *alpha, int gamma)
{
    double lift = 0, plane = gamma;
    for (int j = 0; j < dim; j++) {
        lift += p[j] * p[j];
        plane += alpha[j] * p[j];
    }
    return lift - plane;
}

/* ---- generators: each fills the points of one case for predicate k ---- */

static void gen_uniform(int k, double p[5][4], unsigned long long *s)
{
    for (int i = 0; i < npoints(k); i++)
        for (int j = 0; j < 4; j++)
            p[i][j] = uniform(s, -1, 1);
}

/* Small integer grid points (and integer weights), each value moved by 0 or 1 ulp: many exact
 * degeneracies and many near ones. */
static void gen_grid_ulp(int k, double p[5][4], unsigned long long *s)
{
    for (int i = 0; i < npoints(k); i++)
        for (int j = 0; j < 4; j++)
            p[i][j] = ulp_noise(s, rand_int(s, -3, 3));
}

/* Exactly degenerate: points on an integer line / plane (orientation), on the circle
 * x^2 + y^2 = 25 or the sphere |x| = 3 translated by an integer vector (in-tests), lifted
 * points on an integer plane (power tests). */
static void gen_degenerate(int k, double p[5][4], unsigned long long *s)
{
    static const int circle[12][2] = {{3, 4},   {4, 3},   {-3, 4}, {-4, 3}, {3, -4}, {4, -3},
                                      {-3, -4}, {-4, -3}, {5, 0},  {-5, 0}, {0, 5},  {0, -5}};
    int dim = kinds[k].dim, n = npoints(k), off[3], alpha[3], gamma = rand_int(s, -9, 9);
    for (int j = 0; j < 3; j++) {
        off[j] = rand_int(s, -20, 20);
        alpha[j] = rand_int(s, -5, 5);
    }
    for (int i = 0; i < n; i++) {
        if (!kinds[k].lifted) { /* p = off + t u + r v (v = 0 in 2D: a line) */
            int t = rand_int(s, -6, 6), r = rand_int(s, -6, 6);
            for (int j = 0; j < dim; j++)
                p[i][j] = off[j] + t * alpha[j] + (dim == 3) * r * (j == 0 ? 1 : j == 1 ? 2 : -1);
        } else if (kinds[k].weighted) {
            for (int j = 0; j < dim; j++)
                p[i][j] = rand_int(s, -8, 8);
            p[i][dim] = plane_weight(p[i], dim, alpha, gamma);
        } else if (dim == 2) {
            const int *c = circle[rand_int(s, 0, 11)];
            p[i][0] = off[0] + c[0];
            p[i][1] = off[1] + c[1];
        } else { /* a permutation of (+-1, +-2, +-2) or (+-3, 0, 0): radius 3 */
            int v[3] = {1, 2, 2}, perm = rand_int(s, 0, 2);
            if (rand_int(s, 0, 3) == 0) v[0] = 3, v[1] = v[2] = 0;
            for (int j = 0; j < 3; j++)
                p[i][j] = off[j] + (rand_int(s, 0, 1) ? -1 : 1) * v[(j + perm) % 3];
        }
    }
}

/* Near-degenerate: points computed in floating point on a line / plane / circle / sphere (so
 * off it by rounding), then moved by 0 or 1 ulp. */
static void gen_near(int k, double p[5][4], unsigned long long *s)
{
    int dim = kinds[k].dim, n = npoints(k);
    double c[3], u[3], v[3], radius = uniform(s, 0.1, 10);
    for (int j = 0; j < 3; j++) {
        c[j] = uniform(s, -10, 10);
        u[j] = uniform(s, -1, 1);
        v[j] = uniform(s, -1, 1);
    }
    for (int i = 0; i < n; i++) {
        if (!kinds[k].lifted) {
            double t = uniform(s, -5, 5), r = dim == 3 ? uniform(s, -5, 5) : 0;
            for (int j = 0; j < dim; j++)
                p[i][j] = c[j] + t * u[j] + r * v[j];
        } else {
            double d[3] = {uniform(s, -1, 1), uniform(s, -1, 1), dim == 3 ? uniform(s, -1, 1) : 0};
            double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            for (int j = 0; j < dim; j++)
                p[i][j] = c[j] + radius * d[j] / len;
            if (kinds[k].weighted) { /* near the plane lift = u.x + c0 */
                double lift = 0, plane = c[0];
                for (int j = 0; j < dim; j++) {
                    p[i][j] = uniform(s, -3, 3);
                    lift += p[i][j] * p[i][j];
                    plane += u[j] * p[i][j];
                }
                p[i][dim] = lift - plane;
            }
        }
        for (int j = 0; j < dim + kinds[k].weighted; j++)
            p[i][j] = ulp_noise(s, p[i][j]);
    }
}

/* Every value with a random exponent over the whole double range (subnormals included) and
 * a random sign: the filter's range guards and the exact stage's scaling. */
static void gen_wild_exponents(int k, double p[5][4], unsigned long long *s)
{
    for (int i = 0; i < npoints(k); i++)
        for (int j = 0; j < 4; j++) {
            double m = uniform(s, 1, 2) * (rand_int(s, 0, 1) ? -1 : 1);
            int e = rand_int(s, 0, 9) == 0 ? rand_int(s, -1074, 1023) : rand_int(s, -8, 8);
            p[i][j] = rand_int(s, 0, 7) == 0 ? 0 : ldexp(m, e);
        }
}

/* Multiplies coordinates by 2^e and weights by 2^(2e): exact unless it underflows. Returns 0
 * when a value overflowed (the case is then not usable). */
static int scale_case(int k, double p[5][4], int e)
{
    int dim = kinds[k].dim, finite = 1;
    for (int i = 0; i < npoints(k); i++) {
        for (int j = 0; j < dim; j++)
            p[i][j] = ldexp(p[i][j], e);
        if (kinds[k].weighted) p[i][dim] = ldexp(p[i][dim], 2 * e);
        for (int j = 0; j < dim + kinds[k].weighted; j++)
            finite &= isfinite(p[i][j]) != 0;
    }
    return finite;
}

typedef void (*generator)(int, double[5][4], unsigned long long *);

/* Runs `count` cases of generator g on every predicate, each also rescaled to a huge, a tiny
 * and a subnormal-range magnitude. Requires agreement with the oracle everywhere. */
static void run_generator(const char *name, generator g, int count, int expect_zeros)
{
    for (int k = 0; k < KINDS; k++) {
        unsigned long long seed = 0x5eed0000ull + (unsigned long long)k;
        tally t = {0, 0, 0, 0};
        for (int c = 0; c < count; c++) {
            double p[5][4] = {{0}};
            g(k, p, &seed);
            compare(k, p, &t);
            /* a power of two keeps every degree-homogeneous sign, the oracle still decides */
            int deg = kinds[k].dim + kinds[k].lifted;
            int big = (1000 / deg) - rand_int(&seed, 0, 40),
                tiny = -(1060 / deg) + rand_int(&seed, 0, 20);
            double q[5][4];
            memcpy(q, p, sizeof q);
            if (scale_case(k, q, c % 2 ? big : tiny)) compare(k, q, &t);
        }
        printf("  %-18s %-14s %6ld cases, %5ld zero, %5ld positive, %ld mismatches\n",
               kinds[k].name, name, t.cases, t.zeros, t.positives, t.mismatches);
        CHECK_EQ_INT(t.mismatches, 0);
        if (expect_zeros) CHECK(t.zeros > 0);
    }
}

static void test_exact_sign_on_uniform_random_points(void)
{
    run_generator("uniform", gen_uniform, 3000, 0);
}

static void test_exact_sign_on_ulp_perturbed_integer_grid(void)
{
    run_generator("grid+ulp", gen_grid_ulp, 4000, 0);
}

static void test_exact_sign_on_exactly_degenerate_points(void)
{
    run_generator("degenerate", gen_degenerate, 3000, 1);
}

static void test_exact_sign_on_nearly_degenerate_points(void)
{
    run_generator("near", gen_near, 4000, 0);
}

static void test_exact_sign_on_values_of_any_exponent(void)
{
    run_generator("wild exponent", gen_wild_exponents, 3000, 0);
}

/* The documented conventions on configurations whose answer is known in closed form. */
static void test_sign_conventions_match_the_documentation(void)
{
    double a[4] = {0, 0, 0, 0}, b[4] = {1, 0, 0, 0}, c[4] = {0, 1, 0, 0};
    double below[4] = {0, 0, -1, 0}, above[4] = {0, 0, 1, 0};
    CHECK_EQ_INT(fl_orient2d(a, b, c), 1);
    CHECK_EQ_INT(fl_orient2d(b, a, c), -1);
    CHECK_EQ_INT(fl_orient3d(a, b, c, below), 1);
    CHECK_EQ_INT(fl_orient3d(a, b, c, above), -1);
    /* unit circle / sphere through ccw (positively oriented) points, center inside */
    double p[4] = {1, 0, 0, 0}, q[4] = {0, 1, 0, 0}, r[4] = {-1, 0, 0, 0}, o[4] = {0, 0, 0, 0};
    double far[4] = {5, 5, 5, 0}, s4[4] = {0, 0, 1, 0}, on[4] = {0, -1, 0, 0};
    CHECK_EQ_INT(fl_incircle(p, q, r, o), 1);
    CHECK_EQ_INT(fl_incircle(p, q, r, far), -1);
    CHECK_EQ_INT(fl_incircle(p, q, r, on), 0);
    CHECK_EQ_INT(fl_incircle(q, p, r, o), -1);
    double t0[4] = {1, 0, 0, 0}, t1[4] = {0, 1, 0, 0}, t2[4] = {0, 0, 1, 0}, t3[4] = {-1, 0, 0, 0};
    (void)s4;
    CHECK_EQ_INT(fl_orient3d(t0, t1, t2, t3), 1); /* t3 is below the ccw plane t0 t1 t2 */
    CHECK_EQ_INT(fl_insphere(t0, t1, t2, t3, o), 1);
    CHECK_EQ_INT(fl_insphere(t0, t1, t2, t3, far), -1);
    CHECK_EQ_INT(fl_insphere(t1, t0, t2, t3, o), -1);
    /* weights: equal weights change nothing; a heavy d (big orthogonal circle) is in conflict
     * even outside the circle, a negative-power one is not */
    double wp[3] = {1, 0, 0.5}, wq[3] = {0, 1, 0.5}, wr[3] = {-1, 0, 0.5};
    double wo[3] = {0, 0, 0.5}, wfar[3] = {3, 0, 0.5}, wheavy[3] = {3, 0, 100};
    CHECK_EQ_INT(fl_incircle_weighted(wp, wq, wr, wo), 1);
    CHECK_EQ_INT(fl_incircle_weighted(wp, wq, wr, wfar), -1);
    CHECK_EQ_INT(fl_incircle_weighted(wp, wq, wr, wheavy), 1);
    double w0[4] = {1, 0, 0, 2}, w1[4] = {0, 1, 0, 2}, w2[4] = {0, 0, 1, 2}, w3[4] = {-1, 0, 0, 2};
    double wo3[4] = {0, 0, 0, 2}, wfar3[4] = {5, 5, 5, 2}, wheavy3[4] = {5, 5, 5, 1000};
    CHECK_EQ_INT(fl_insphere_weighted(w0, w1, w2, w3, wo3), 1);
    CHECK_EQ_INT(fl_insphere_weighted(w0, w1, w2, w3, wfar3), -1);
    CHECK_EQ_INT(fl_insphere_weighted(w0, w1, w2, w3, wheavy3), 1);
}

/* Overflow in the differences (opposite huge values) and products of subnormals. */
static void test_extreme_values_are_decided_exactly(void)
{
    double M = DBL_MAX, d = 0x1p-1074;
    double a[4] = {-M, -M, -M, 0}, b[4] = {M, -M, -M, 0}, c[4] = {-M, M, -M, 0},
           e[4] = {-M, -M, M, 0};
    CHECK_EQ_INT(fl_orient2d(a, b, c), 1);
    CHECK_EQ_INT(fl_orient3d(a, b, c, e), -1);
    double mid[4] = {0, 0, 0, 0};
    CHECK_EQ_INT(fl_orient2d(a, mid, (double[]){M, M}), 0);
    double ta[2] = {0, 0}, tb[2] = {d, 0}, tc[2] = {0, d}, td[2] = {d, d}, te[2] = {2 * d, 2 * d};
    CHECK_EQ_INT(fl_orient2d(ta, tb, tc), 1);
    CHECK_EQ_INT(fl_incircle(ta, tb, tc, td), 0);
    CHECK_EQ_INT(fl_incircle(ta, tb, tc, te), -1);
    CHECK_EQ_INT(fl_orient2d(ta, td, te), 0);
    /* a subnormal offset next to huge values: only the exact stage sees it */
    double h0[2] = {0x1p1000, 0}, h1[2] = {0, 0x1p1000}, h2[2] = {0x1p999, 0x1p999};
    CHECK_EQ_INT(fl_orient2d(h0, h1, h2), 0);
    h2[0] = 0x1p999 + 0x1p947;
    CHECK_EQ_INT(fl_orient2d(h0, h1, h2), -1);
}

FL_TEST_MAIN(FL_TEST_CASE(test_sign_conventions_match_the_documentation),
             FL_TEST_CASE(test_extreme_values_are_decided_exactly),
             FL_TEST_CASE(test_exact_sign_on_uniform_random_points),
             FL_TEST_CASE(test_exact_sign_on_ulp_perturbed_integer_grid),
             FL_TEST_CASE(test_exact_sign_on_exactly_degenerate_points),
             FL_TEST_CASE(test_exact_sign_on_nearly_degenerate_points),
             FL_TEST_CASE(test_exact_sign_on_values_of_any_exponent))

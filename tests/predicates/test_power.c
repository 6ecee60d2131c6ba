/* The skin's power-distance predicates (src/predicates/power.c) against an independent exact
 * evaluation of the geometry they decide, in GMP rationals (mpq_set_d is exact). The oracle
 * never forms the predicates' determinants: it solves for the focus f of the simplex (the point
 * of aff X with equal power to its balls), builds the point the test is about and compares
 * powers directly:
 *  - link test of the walk: v = f + q / t with x - f = p + q, p in the direction space of X and
 *    q orthogonal to it; the sign is that of pi_b(v) - pi_X(v);
 *  - bordered, link mode: the sign of pi_b(f) - pi_X(f);
 *  - bordered, power mode: minus the sign of pi_X(f).
 * Inputs: small integer lattices (many exact zeros), random doubles, near-zero cases bisected
 * to adjacent doubles on the oracle's zero set, and copies translated by a power of two or
 * scaled by one (coordinates by 2^m, weights by 2^2m), which must keep every sign: the scaled
 * copies lie outside both filters' ranges, so the exact stages decide them. */
#include <gmp.h>
#include <math.h>
#include <string.h>

#include "fl_test.h"
#include "predicates/power.h"

static unsigned long long rng = 20261124;

/* pi_z(p) = |p - c|^2 - w for ball z = (c, w). */
static void oracle_power(mpq_t r, const double *z, const mpq_t p[3])
{
    mpq_t d;
    mpq_init(d);
    mpq_set_d(r, z[3]);
    mpq_neg(r, r);
    for (int c = 0; c < 3; c++) {
        mpq_set_d(d, z[c]);
        mpq_sub(d, p[c], d);
        mpq_mul(d, d, d);
        mpq_add(r, r, d);
    }
    mpq_clear(d);
}

/* Solves A y = rhs (n <= 3) in place by Gaussian elimination; 0 when A is singular. */
static int oracle_solve(mpq_t A[3][3], mpq_t rhs[3], int n)
{
    mpq_t f, t;
    mpq_inits(f, t, NULL);
    int ok = 1;
    for (int col = 0; col < n && ok; col++) {
        int piv = -1;
        for (int r = col; r < n && piv < 0; r++)
            if (mpq_sgn(A[r][col])) piv = r;
        if (piv < 0) {
            ok = 0;
            break;
        }
        for (int j = 0; j < n; j++)
            mpq_swap(A[piv][j], A[col][j]);
        mpq_swap(rhs[piv], rhs[col]);
        for (int r = 0; r < n; r++) {
            if (r == col || !mpq_sgn(A[r][col])) continue;
            mpq_div(f, A[r][col], A[col][col]);
            for (int j = 0; j < n; j++) {
                mpq_mul(t, f, A[col][j]);
                mpq_sub(A[r][j], A[r][j], t);
            }
            mpq_mul(t, f, rhs[col]);
            mpq_sub(rhs[r], rhs[r], t);
        }
    }
    for (int r = 0; r < n && ok; r++)
        mpq_div(rhs[r], rhs[r], A[r][r]);
    mpq_clears(f, t, NULL);
    return ok;
}

/* The simplex z[0..k]: its edge vectors e[i] = z[i+1] - z[0] and Gram matrix. */
typedef struct oracle_simplex {
    int k;
    mpq_t a[3], e[3][3], G[3][3];
} oracle_simplex;

static void simplex_init(oracle_simplex *S, const double *const *z, int k)
{
    mpq_t t;
    mpq_init(t);
    S->k = k;
    for (int c = 0; c < 3; c++) {
        mpq_init(S->a[c]);
        mpq_set_d(S->a[c], z[0][c]);
    }
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 3; c++) {
            mpq_init(S->e[i][c]);
            mpq_init(S->G[i][c]);
            if (i < k) {
                mpq_set_d(S->e[i][c], z[i + 1][c]);
                mpq_sub(S->e[i][c], S->e[i][c], S->a[c]);
            }
        }
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++)
            for (int c = 0; c < 3; c++) {
                mpq_mul(t, S->e[i][c], S->e[j][c]);
                mpq_add(S->G[i][j], S->G[i][j], t);
            }
    mpq_clear(t);
}

static void simplex_clear(oracle_simplex *S)
{
    for (int c = 0; c < 3; c++)
        mpq_clear(S->a[c]);
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 3; c++) {
            mpq_clear(S->e[i][c]);
            mpq_clear(S->G[i][c]);
        }
}

/* out = base + sum eta_i e_i (base NULL: 0) with G eta = rhs; rhs is overwritten by eta and
 * cleared. 0 when G is singular. */
static int span_point(const oracle_simplex *S, mpq_t rhs[3], const mpq_t *base, mpq_t out[3])
{
    mpq_t A[3][3], t;
    mpq_init(t);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            mpq_init(A[i][j]);
            mpq_set(A[i][j], S->G[i][j]);
        }
    int ok = oracle_solve(A, rhs, S->k);
    for (int c = 0; c < 3; c++) {
        if (base)
            mpq_set(out[c], base[c]);
        else
            mpq_set_ui(out[c], 0, 1);
        for (int i = 0; i < S->k && ok; i++) {
            mpq_mul(t, rhs[i], S->e[i][c]);
            mpq_add(out[c], out[c], t);
        }
    }
    for (int i = 0; i < 3; i++) {
        mpq_clear(rhs[i]);
        for (int j = 0; j < 3; j++)
            mpq_clear(A[i][j]);
    }
    mpq_clear(t);
    return ok;
}

/* Projects y (relative to a) onto the direction space of S: out = sum alpha_i e_i with
 * G alpha = (e_i . y). 0 when G is singular. */
static int project(const oracle_simplex *S, const mpq_t y[3], mpq_t out[3])
{
    mpq_t rhs[3], t;
    mpq_init(t);
    for (int i = 0; i < 3; i++)
        mpq_init(rhs[i]);
    for (int i = 0; i < S->k; i++)
        for (int c = 0; c < 3; c++) {
            mpq_mul(t, S->e[i][c], y[c]);
            mpq_add(rhs[i], rhs[i], t);
        }
    mpq_clear(t);
    return span_point(S, rhs, NULL, out);
}

/* The focus of the balls z[0..k]: the point f = a + sum eta_i e_i of aff X with equal power
 * to all of them, i.e. e_i . (f - a) = s_i / 2 with s_i = |e_i|^2 - w_i + w_0 (G eta = s / 2).
 * 0 when the centres are affinely dependent. */
static int focus(const oracle_simplex *S, const double *const *z, mpq_t f[3])
{
    mpq_t rhs[3], t;
    mpq_init(t);
    for (int i = 0; i < 3; i++)
        mpq_init(rhs[i]);
    for (int i = 0; i < S->k; i++) {
        mpq_set(rhs[i], S->G[i][i]);
        mpq_set_d(t, z[i + 1][3]);
        mpq_sub(rhs[i], rhs[i], t);
        mpq_set_d(t, z[0][3]);
        mpq_add(rhs[i], rhs[i], t);
        mpq_set_ui(t, 1, 2);
        mpq_mul(rhs[i], rhs[i], t);
    }
    mpq_clear(t);
    return span_point(S, rhs, (const mpq_t *)S->a, f);
}

/* Sign of pi_b(p) - pi_0(p), stored in val when not NULL; *consistent is cleared unless every
 * ball of X has the same power at p (p lies in aff nu_X, so pi_X(p) is well defined). */
static int power_difference_sign(const double *const *z, int k, const double *zb, const mpq_t p[3],
                                 int *consistent, mpq_ptr val)
{
    mpq_t p0, pi, pb;
    mpq_inits(p0, pi, pb, NULL);
    oracle_power(p0, z[0], p);
    for (int i = 1; i <= k; i++) {
        oracle_power(pi, z[i], p);
        if (!mpq_equal(pi, p0)) *consistent = 0;
    }
    oracle_power(pb, zb, p);
    mpq_sub(pb, pb, p0);
    int s = mpq_sgn(pb);
    if (val) mpq_set(val, pb);
    mpq_clears(p0, pi, pb, NULL);
    return s;
}

/* The walk's link test from its definition (pts as fl_power_link_*); 2 when the centres of X
 * are affinely dependent. val (if not NULL) gets pi_b(v) - pi_X(v). */
static int oracle_link(const double *const *pts, int k, double t, int *consistent, mpq_ptr val)
{
    oracle_simplex S;
    simplex_init(&S, pts, k);
    mpq_t f[3], y[3], p[3], v[3], tq;
    mpq_init(tq);
    for (int c = 0; c < 3; c++)
        mpq_inits(f[c], y[c], p[c], v[c], NULL);
    int sign = 2;
    if (focus(&S, pts, f)) {
        for (int c = 0; c < 3; c++) {
            mpq_set_d(y[c], pts[4][c]);
            mpq_sub(y[c], y[c], f[c]);
        }
        project(&S, y, p);
        mpq_set_d(tq, t);
        for (int c = 0; c < 3; c++) { /* v = f + (y - p) / t */
            mpq_sub(v[c], y[c], p[c]);
            mpq_div(v[c], v[c], tq);
            mpq_add(v[c], v[c], f[c]);
        }
        sign = power_difference_sign(pts, k, pts[3], v, consistent, val);
    }
    for (int c = 0; c < 3; c++)
        mpq_clears(f[c], y[c], p[c], v[c], NULL);
    mpq_clear(tq);
    simplex_clear(&S);
    return sign;
}

/* The bordered determinant's sign from its meaning (z as fl_power_bordered_*); 2 when the
 * centres of X are affinely dependent. val (if not NULL) gets pi_b(f) - pi_X(f) in link mode,
 * pi_X(f) in power mode. */
static int oracle_bordered(const double *const *z, int k, int mode, int *consistent, mpq_ptr val)
{
    oracle_simplex S;
    simplex_init(&S, z, k);
    mpq_t f[3], p0;
    mpq_init(p0);
    for (int c = 0; c < 3; c++)
        mpq_init(f[c]);
    int sign = 2;
    if (focus(&S, z, f)) {
        if (mode == FL_BORDERED_LINK) {
            sign = power_difference_sign(z, k, z[k + 1], f, consistent, val);
        } else {
            power_difference_sign(z, k, z[0], f, consistent, NULL);
            oracle_power(p0, z[0], f);
            sign = -mpq_sgn(p0);
            if (val) mpq_set(val, p0);
        }
    }
    for (int c = 0; c < 3; c++)
        mpq_clear(f[c]);
    mpq_clear(p0);
    simplex_clear(&S);
    return sign;
}

/* ---- inputs ---- */

/* Five balls (the last one is the query point of the link test; its weight is unused). */
typedef struct config {
    double b[5][4];
    double t;
} config;

static double lattice(int lo, int hi)
{
    return (double)(lo + (int)(fl_test_rand_u64(&rng) % (unsigned)(hi - lo + 1)));
}

static void random_config(config *C, int regime)
{
    for (int i = 0; i < 5; i++) {
        for (int c = 0; c < 3; c++)
            C->b[i][c] = regime ? fl_test_rand01(&rng) * 2 - 1 : lattice(-3, 3);
        C->b[i][3] = regime ? fl_test_rand01(&rng) * 0.5 : lattice(-4, 8);
    }
    static const double lattice_t[4] = {0.5, 0.25, 0.75, 0.625};
    C->t = regime ? fl_test_rand01(&rng) : lattice_t[fl_test_rand_u64(&rng) % 4];
    if (!(C->t > 0)) C->t = 0.5;
}

/* Pointers as the link predicates take them: X's balls, b in the rows beyond k, b, x. */
static void link_pts(const config *C, int k, const double *pts[5])
{
    for (int i = 0; i < 3; i++)
        pts[i] = i <= k ? C->b[i] : C->b[3];
    pts[3] = C->b[3];
    pts[4] = C->b[4];
}

/* Pointers as the bordered predicates take them: X's balls z[0..k], then b = ball 4. */
static void bordered_pts(const config *C, int k, const double *z[5])
{
    for (int i = 0; i <= k; i++)
        z[i] = C->b[i];
    z[k + 1] = C->b[4];
}

/* A lattice configuration whose simplex has mutually orthogonal edges of squared length a power
 * of two, so that the focus, the projections and v are dyadic rationals: z_1..z_3 are z_0 plus
 * the rows of a signed, axis-permuted copy of one of two orthogonal frames, scaled by 1 or 2. */
static void frame_config(config *C)
{
    static const double frame[2][3][3] = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                          {{1, 1, 0}, {1, -1, 0}, {0, 0, 1}}};
    static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                   {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    random_config(C, 0);
    int f = (int)(fl_test_rand_u64(&rng) % 2), q = (int)(fl_test_rand_u64(&rng) % 6);
    for (int i = 0; i < 3; i++) {
        double sc = (fl_test_rand_u64(&rng) % 2 ? 2 : 1) * (fl_test_rand_u64(&rng) % 2 ? -1 : 1);
        for (int c = 0; c < 3; c++)
            C->b[i + 1][c] = C->b[0][c] + sc * frame[f][i][perm[q][c]];
    }
}

/* *w += val when the sum is exactly a double; 0 (w unchanged) when it is not. */
static int add_exactly(double *w, mpq_srcptr val)
{
    mpq_t sum, back;
    mpq_inits(sum, back, NULL);
    mpq_set_d(sum, *w);
    mpq_add(sum, sum, val);
    double d = mpq_get_d(sum);
    mpq_set_d(back, d);
    int ok = mpq_equal(back, sum) && isfinite(d);
    if (ok) *w = d;
    mpq_clears(sum, back, NULL);
    return ok;
}

/* Turns a frame configuration into an exact zero of the walk's link test with simplex size k:
 * the weight of b grows by pi_b(v) - pi_X(v) (v does not depend on it). 0 when that is not a
 * double. */
static int link_zero(config *C, int k)
{
    const double *pts[5];
    link_pts(C, k, pts);
    mpq_t val;
    mpq_init(val);
    int consistent = 1, ok = 0;
    if (oracle_link(pts, k, C->t, &consistent, val) != 2) ok = add_exactly(&C->b[3][3], val);
    mpq_clear(val);
    return ok;
}

/* The same for a bordered determinant: in link mode the weight of b grows by pi_b(f) - pi_X(f);
 * in power mode every weight of X grows by pi_X(f), which leaves f in place (it depends on
 * weight differences only) and makes pi_X(f) zero. */
static int bordered_zero(config *C, int k, int mode)
{
    const double *z[5];
    bordered_pts(C, k, z);
    mpq_t val;
    mpq_init(val);
    int consistent = 1, ok = oracle_bordered(z, k, mode, &consistent, val) != 2;
    if (ok && mode == FL_BORDERED_LINK) ok = add_exactly(&C->b[4][3], val);
    for (int i = 0; i <= k && ok && mode == FL_BORDERED_POWER; i++)
        ok = add_exactly(&C->b[i][3], val);
    mpq_clear(val);
    return ok;
}

/* The copy with coordinates (query point included) times 2^m and weights times 2^2m, then
 * translated by 2^shift in every coordinate (exact for the lattice inputs used with it). */
static void transformed(const config *C, config *D, int m, int shift)
{
    *D = *C;
    for (int i = 0; i < 5; i++) {
        for (int c = 0; c < 3; c++)
            D->b[i][c] = ldexp(C->b[i][c], m) + (shift ? ldexp(1, shift) : 0);
        D->b[i][3] = ldexp(C->b[i][3], 2 * m);
    }
}

/* ---- tallies ---- */

typedef struct tally {
    int cases, zeros, exact_wrong, filter_decided, filter_wrong, inconsistent;
} tally;

static void check_link(const config *C, int k, tally *T)
{
    const double *pts[5];
    link_pts(C, k, pts);
    int consistent = 1;
    int want = oracle_link(pts, k, C->t, &consistent, NULL);
    if (want == 2) return;
    T->cases++;
    T->zeros += want == 0;
    T->inconsistent += !consistent;
    int ex = fl_power_link_exact(pts, k, C->t), fi = fl_power_link_filter(pts, k, C->t);
    T->exact_wrong += ex != want;
    T->filter_decided += fi != 0;
    T->filter_wrong += fi != 0 && fi != want;
}

static void check_bordered(const config *C, int k, int mode, tally *T)
{
    const double *z[5];
    bordered_pts(C, k, z);
    int consistent = 1;
    int want = oracle_bordered(z, k, mode, &consistent, NULL);
    if (want == 2) return;
    T->cases++;
    T->zeros += want == 0;
    T->inconsistent += !consistent;
    int ex = fl_power_bordered_exact(z, k, mode), fi = fl_power_bordered_filter(z, k, mode);
    T->exact_wrong += ex != want || fl_power_bordered_sign(z, k, mode) != want;
    T->filter_decided += fi != 2;
    T->filter_wrong += fi != 2 && fi != want;
}

/* One scalar input of C (ball i, component c) moved by bisection between lo and hi, where
 * the oracle `sign_at` differs, until lo and hi are adjacent doubles; C keeps the endpoint
 * whose sign is nonzero and nearest the zero set. 0 when the end signs do not differ. */
static int bisect(config *C, int i, int c, double lo, double hi,
                  int (*sign_at)(const config *, const void *), const void *arg)
{
    C->b[i][c] = lo;
    int slo = sign_at(C, arg);
    C->b[i][c] = hi;
    int shi = sign_at(C, arg);
    if (slo == 2 || shi == 2 || slo == shi || !slo || !shi) return 0;
    for (int step = 0; step < 1100; step++) {
        double mid = lo + (hi - lo) / 2;
        if (mid == lo || mid == hi) break;
        C->b[i][c] = mid;
        int s = sign_at(C, arg);
        if (s == 2) return 0;
        if (s == 0) return 1; /* landed on the zero set itself */
        if (s == slo)
            lo = mid;
        else
            hi = mid;
    }
    C->b[i][c] = lo;
    return 1;
}

typedef struct link_arg {
    int k;
} link_arg;

static int link_sign_at(const config *C, const void *arg)
{
    int k = ((const link_arg *)arg)->k, consistent = 1;
    const double *pts[5];
    link_pts(C, k, pts);
    return oracle_link(pts, k, C->t, &consistent, NULL);
}

typedef struct bordered_arg {
    int k, mode;
} bordered_arg;

static int bordered_sign_at(const config *C, const void *arg)
{
    const bordered_arg *A = arg;
    int consistent = 1;
    const double *z[5];
    bordered_pts(C, A->k, z);
    return oracle_bordered(z, A->k, A->mode, &consistent, NULL);
}

/* ---- tests ---- */

/* The five families every test sees (one tally each): lattice, random doubles, exact zeros
 * built on orthogonal frames, those zeros with the adjusted weight moved by one ulp either way
 * (nonzero, far inside any rounding band), and (link tests) x or w_b bisected onto the zero set
 * of a random configuration. */
enum { LAT, RND, ZERO, NEAR, BISECT, FAMILIES };
static const char *const family_name[FAMILIES] = {"lattice", "random", "zero", "ulp", "bisected"};

static void check_tallies(const tally *T, const char *what, int k)
{
    for (int f = 0; f < FAMILIES; f++) {
        CHECK_MSG(T[f].exact_wrong == 0, "%s k %d %s: exact stage wrong in %d of %d", what, k,
                  family_name[f], T[f].exact_wrong, T[f].cases);
        CHECK_MSG(T[f].filter_wrong == 0, "%s k %d %s: filter wrong in %d of %d", what, k,
                  family_name[f], T[f].filter_wrong, T[f].cases);
        CHECK_MSG(T[f].inconsistent == 0, "%s k %d %s: oracle inconsistent", what, k,
                  family_name[f]);
    }
    /* the families are what they say: zeros are zeros, the rest has cases */
    CHECK_MSG(T[ZERO].cases > 500 && T[ZERO].zeros == T[ZERO].cases, "%s k %d: %d zeros of %d",
              what, k, T[ZERO].zeros, T[ZERO].cases);
    CHECK_MSG(T[NEAR].cases > 500 && T[NEAR].zeros == 0, "%s k %d: %d ulp cases, %d zeros", what, k,
              T[NEAR].cases, T[NEAR].zeros);
    /* a filter that never decides would pass the checks above: it must decide random inputs */
    CHECK_MSG(T[RND].filter_decided > T[RND].cases * 9 / 10, "%s k %d: filter decided %d of %d",
              what, k, T[RND].filter_decided, T[RND].cases);
}

static void test_link_test_matches_the_power_difference_at_v(void)
{
    for (int k = 0; k <= 2; k++) {
        tally T[FAMILIES] = {{0}};
        for (int n = 0; n < 2000; n++) {
            config C;
            random_config(&C, 0);
            check_link(&C, k, &T[LAT]);
            random_config(&C, 1);
            check_link(&C, k, &T[RND]);
            frame_config(&C);
            if (!link_zero(&C, k)) continue;
            check_link(&C, k, &T[ZERO]);
            double w = C.b[3][3];
            C.b[3][3] = nextafter(w, n % 2 ? INFINITY : -INFINITY);
            check_link(&C, k, &T[NEAR]);
        }
        for (int n = 0; n < 150; n++) { /* x moved onto the zero set along one coordinate */
            config C;
            random_config(&C, 1);
            link_arg A = {k};
            if (bisect(&C, 4, (int)(fl_test_rand_u64(&rng) % 3), -4, 4, link_sign_at, &A))
                check_link(&C, k, &T[BISECT]);
        }
        CHECK_MSG(T[BISECT].cases > 50, "k %d: %d bisected cases", k, T[BISECT].cases);
        check_tallies(T, "link", k);
    }
}

static void test_bordered_signs_match_the_focus_powers(void)
{
    for (int mode = FL_BORDERED_LINK; mode <= FL_BORDERED_POWER; mode++)
        for (int k = 0; k <= (mode == FL_BORDERED_LINK ? 2 : 3); k++) {
            tally T[FAMILIES] = {{0}};
            for (int n = 0; n < 2000; n++) {
                config C;
                random_config(&C, 0);
                check_bordered(&C, k, mode, &T[LAT]);
                random_config(&C, 1);
                check_bordered(&C, k, mode, &T[RND]);
                frame_config(&C);
                if (!bordered_zero(&C, k, mode)) continue;
                check_bordered(&C, k, mode, &T[ZERO]);
                double *w = &C.b[mode == FL_BORDERED_LINK ? 4 : 0][3];
                *w = nextafter(*w, n % 2 ? INFINITY : -INFINITY);
                check_bordered(&C, k, mode, &T[NEAR]);
            }
            /* link mode: the weight of b bisected onto the zero set (it enters linearly) */
            bordered_arg A = {k, mode};
            for (int n = 0; n < 150 && mode == FL_BORDERED_LINK; n++) {
                config C;
                random_config(&C, 1);
                if (bisect(&C, 4, 3, -16, 16, bordered_sign_at, &A))
                    check_bordered(&C, k, mode, &T[BISECT]);
            }
            if (mode == FL_BORDERED_LINK)
                CHECK_MSG(T[BISECT].cases > 50, "k %d: %d bisected cases", k, T[BISECT].cases);
            check_tallies(T, mode == FL_BORDERED_LINK ? "bordered link" : "bordered power", k);
        }
}

/* Scaling every coordinate by 2^m and every weight by 2^2m multiplies both determinants by a
 * positive factor, and a common translation leaves them unchanged: the signs of lattice
 * configurations (half of them exact zeros) stay those of the oracle on the originals, also
 * far outside the filters' ranges (2^+-500: the exact stages alone). */
static void test_signs_survive_power_of_two_scaling_and_translation(void)
{
    static const int scale[][2] = {{0, 10}, {0, 40}, {500, 0}, {-500, 0}, {-40, 12}, {300, 0}};
    int mismatches = 0, checked = 0, zeros = 0;
    for (int n = 0; n < 1500; n++) {
        config C, D;
        int k = (int)(fl_test_rand_u64(&rng) % 4), consistent = 1;
        int mode = k == 3 ? FL_BORDERED_POWER : (int)(fl_test_rand_u64(&rng) % 2);
        frame_config(&C);
        if (n % 2 && k <= 2) link_zero(&C, k);
        if (n % 2) bordered_zero(&C, k, mode);
        const double *pts[5], *z[5];
        link_pts(&C, k, pts);
        int want_link = k <= 2 ? oracle_link(pts, k, C.t, &consistent, NULL) : 2;
        bordered_pts(&C, k, z);
        int want_bord = oracle_bordered(z, k, mode, &consistent, NULL);
        zeros += (want_link == 0) + (want_bord == 0);
        for (size_t s = 0; s < sizeof scale / sizeof scale[0]; s++) {
            transformed(&C, &D, scale[s][0], scale[s][1]);
            if (want_link != 2) {
                link_pts(&D, k, pts);
                int fi = fl_power_link_filter(pts, k, D.t);
                mismatches += fl_power_link_exact(pts, k, D.t) != want_link;
                mismatches += fi != 0 && fi != want_link;
                checked++;
            }
            if (want_bord != 2) {
                bordered_pts(&D, k, z);
                mismatches += fl_power_bordered_sign(z, k, mode) != want_bord;
                mismatches += fl_power_bordered_exact(z, k, mode) != want_bord;
                checked++;
            }
        }
    }
    CHECK_EQ_INT(mismatches, 0);
    CHECK_MSG(checked > 10000, "%d checked", checked);
    CHECK_MSG(zeros > 500, "%d zeros", zeros);
}

/* What the predicates cannot decide they say so (2, or 0 for the link filter), never a sign. */
static void test_out_of_domain_inputs_are_refused(void)
{
    config C;
    random_config(&C, 1);
    const double *pts[5], *z[5];
    link_pts(&C, 2, pts);
    CHECK_EQ_INT(fl_power_link_exact(pts, 3, 0.5), 2);
    CHECK_EQ_INT(fl_power_link_filter(pts, 3, 0.5), 0);
    CHECK_EQ_INT(fl_power_link_exact(pts, 2, 0), 2);
    CHECK_EQ_INT(fl_power_link_exact(pts, 2, 1), 2);
    CHECK_EQ_INT(fl_power_link_exact(pts, 2, NAN), 2);
    CHECK_EQ_INT(fl_power_link_filter(pts, 2, 1), 0);
    CHECK_EQ_INT(fl_power_link_exact(pts, 2, 0x1p-1010), 2); /* 1 - et > 1000 */
    C.b[4][1] = NAN;
    CHECK_EQ_INT(fl_power_link_filter(pts, 2, 0.5), 0);
    CHECK_EQ_INT(fl_power_link_exact(pts, 2, 0.5), 2);
    C.b[4][1] = 0.25;
    C.b[1][3] = INFINITY;
    CHECK_EQ_INT(fl_power_link_exact(pts, 2, 0.5), 2);
    bordered_pts(&C, 2, z);
    CHECK_EQ_INT(fl_power_bordered_filter(z, 2, FL_BORDERED_POWER), 2);
    CHECK_EQ_INT(fl_power_bordered_exact(z, 2, FL_BORDERED_POWER), 2);
    CHECK_EQ_INT(fl_power_bordered_sign(z, 2, FL_BORDERED_LINK), 2);
}

FL_TEST_MAIN(FL_TEST_CASE(test_link_test_matches_the_power_difference_at_v),
             FL_TEST_CASE(test_bordered_signs_match_the_focus_powers),
             FL_TEST_CASE(test_signs_survive_power_of_two_scaling_and_translation),
             FL_TEST_CASE(test_out_of_domain_inputs_are_refused))

/* The skin function by point location in the mixed complex (src/skin/skin_cell.c) against
 * the definition and against the candidate scan:
 *  - on random ball sets (negative weights included, several t) the walk equals the skin
 *    function from its definition (skin_oracle.h: min over subsets of <= 4 balls, long
 *    double) EVERYWHERE, positive values and points outside the hull included (the mixed cells
 *    tile space), and it answers almost every query itself (fallbacks to the scan counted);
 *  - the answer does not depend on where the walk starts (the shared hint of
 *    fl_skin_function_value: forward and backward orders agree);
 *  - on degenerate sets (a lattice of equal balls: cospherical everywhere; mirror twins 2^-56
 *    apart, as B* of a symmetric solid has) the walk equals the scan wherever either is <= 0
 *    (where the scan is G, docs/skin.md) and is never above the scan (an upper bound of G). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "fl_test.h"
#include "skin_rng.h"
#include "skin/skin_internal.h"
/* only skin_oracle_value is used here; the header's other oracles are static */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "skin_oracle.h"
#pragma GCC diagnostic pop

static uint64_t rng_state = 0x243f6a8885a308d3ULL;

static double rnd(void)
{
    return skin_rng_next(&rng_state);
}

/* Next query: mostly a small step from the previous one (as the mesher's neighbouring grid
 * points), sometimes a jump anywhere in [lo, hi]^3. */
static void next_point(double x[3], double lo, double hi, double step)
{
    int jump = rnd() < 0.1;
    for (int c = 0; c < 3; c++)
        x[c] = jump ? lo + (hi - lo) * rnd() : fmin(hi, fmax(lo, x[c] + step * (2 * rnd() - 1)));
}

/* n random balls in [0, 4]^3, radii 0.5..1.2, every fifth with a negative weight. */
static void random_balls(double *b, int n)
{
    for (int i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++)
            b[4 * i + c] = 4 * rnd();
        double r = 0.5 + 0.7 * rnd();
        b[4 * i + 3] = i % 5 == 4 ? -0.3 * r * r : r * r;
    }
}

static void test_walk_matches_definition_everywhere(void)
{
    enum { N = 14, Q = 500 };
    static const double ts[3] = {0.5, 0.25, 0.8};
    double b[4 * N];
    for (int round = 0; round < 3; round++) {
        double t = ts[round];
        random_balls(b, N);
        fl_skin_function *g = NULL;
        fl_error err;
        CHECK_STATUS(fl_skin_function_new(b, N, t, &g, &err), FL_OK, &err);
        if (!g) continue;
        CHECK(g->walkable); /* more than 8 balls: the regular-triangulation path */
        uint32_t start = 0;
        int fallbacks = 0, negatives = 0, outside = 0;
        double x[3] = {2, 2, 2};
        for (int q = 0; q < Q; q++) {
            next_point(x, -0.5, 4.5, 0.2);
            uint32_t before = start = UINT32_MAX - 1; /* no valid start: found cells set it */
            if (q % 2) before = start = (uint32_t)(rnd() * (double)g->simplex_count);
            double got = skin_value_walk(g, x, &start);
            fallbacks += start == before;
            double want = (double)skin_oracle_value(b, N, t, x);
            negatives += want < 0;
            outside += x[0] < 0 || x[0] > 4 || x[1] < 0 || x[1] > 4 || x[2] < 0 || x[2] > 4;
            CHECK_MSG(fabs(got - want) <= 1e-9 * (1 + fabs(want)),
                      "t %g: G(%.17g, %.17g, %.17g) walk %.17g, definition %.17g", t, x[0], x[1],
                      x[2], got, want);
        }
        CHECK_MSG(negatives > Q / 100 && outside > Q / 10, "%d negative, %d outside", negatives,
                  outside);
        CHECK_MSG(fallbacks < Q / 20, "t %g: %d of %d queries fell back to the scan", t, fallbacks,
                  Q);
        fl_skin_function_free(g);
    }
}

static void test_value_does_not_depend_on_the_start(void)
{
    enum { N = 40, Q = 3000 };
    static double b[4 * N], pts[3 * Q], fwd[Q];
    random_balls(b, N);
    fl_skin_function *g = NULL;
    fl_error err;
    CHECK_STATUS(fl_skin_function_new(b, N, 0.5, &g, &err), FL_OK, &err);
    if (!g) return;
    double x[3] = {2, 2, 2};
    for (int q = 0; q < Q; q++) {
        next_point(x, -1, 5, 0.1);
        for (int c = 0; c < 3; c++)
            pts[3 * q + c] = x[c];
        fwd[q] = fl_skin_function_value(g, x);
    }
    int bad = 0;
    for (int q = Q - 1; q >= 0; q--) { /* the shared hint now comes from the other side */
        double back = fl_skin_function_value(g, pts + 3 * q);
        bad += !(fabs(back - fwd[q]) <= 1e-10 * (1 + fabs(fwd[q])));
    }
    CHECK_MSG(bad == 0, "%d of %d values changed with the evaluation order", bad, Q);
    fl_skin_function_free(g);
}

/* Compares walk and scan at Q points of [lo, hi]^3; returns the number of negative values. */
static int walk_vs_scan(const double *b, int n, double t, double lo, double hi, int q_count)
{
    fl_skin_function *g = NULL;
    fl_error err;
    CHECK_STATUS(fl_skin_function_new(b, (size_t)n, t, &g, &err), FL_OK, &err);
    if (!g) return 0;
    int negatives = 0;
    uint32_t start = 0;
    double x[3] = {0.5 * (lo + hi), 0.5 * (lo + hi), 0.5 * (lo + hi)};
    for (int q = 0; q < q_count; q++) {
        next_point(x, lo, hi, 0.15);
        if (q % 3 == 0) /* grid-like points: on the symmetry planes of the lattice */
            for (int c = 0; c < 3; c++)
                x[c] = round(x[c] * 8) / 8;
        double w = skin_value_walk(g, x, &start), s = skin_value_scan(g, x);
        negatives += s < 0;
        if (s <= 0 || w <= 0)
            CHECK_MSG(fabs(w - s) <= 1e-9 * (1 + fabs(s)), "at (%.17g, %.17g, %.17g): walk %.17g, "
                      "scan %.17g", x[0], x[1], x[2], w, s);
        else
            CHECK_MSG(w <= s + 1e-9 * (1 + fabs(s)), "walk %.17g above the scan %.17g", w, s);
    }
    fl_skin_function_free(g);
    return negatives;
}

static void test_degenerate_sets_walk_equals_scan(void)
{
    /* a 3x3x3 lattice of equal balls (every lattice cube cospherical) with negative balls at
     * the cube centres, and each ball on a symmetry plane twinned 2^-56 off it */
    static double b[4 * 128];
    int n = 0;
    for (int i = -1; i <= 1; i++)
        for (int j = -1; j <= 1; j++)
            for (int k = -1; k <= 1; k++) {
                double z[3] = {i, j, k};
                for (int c = 0; c < 4; c++)
                    b[4 * n + c] = c < 3 ? z[c] : 0.36;
                n++;
                if (i == 0 || j == 0 || k == 0) {
                    for (int c = 0; c < 4; c++)
                        b[4 * n + c] = b[4 * (n - 1) + c];
                    for (int c = 0; c < 3; c++)
                        if (z[c] == 0) b[4 * n + c] = ldexp(1, -56);
                    n++;
                }
            }
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            for (int k = 0; k < 2; k++) {
                double z[4] = {i - 0.5, j - 0.5, k - 0.5, -0.05};
                for (int c = 0; c < 4; c++)
                    b[4 * n + c] = z[c];
                n++;
            }
    int neg = walk_vs_scan(b, n, 0.5, -1.8, 1.8, 4000);
    CHECK_MSG(neg > 400, "%d negative", neg);
    neg = walk_vs_scan(b, n, 0.3, -1.8, 1.8, 2000);
    CHECK_MSG(neg > 200, "%d negative", neg);
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_walk_matches_definition_everywhere),
        FL_TEST_CASE(test_value_does_not_depend_on_the_start),
        FL_TEST_CASE(test_degenerate_sets_walk_equals_scan),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}

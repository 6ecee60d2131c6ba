/* The index's bound on power faces that have no Voronoi box (src/skin/skin_clip.c, round 14):
 * faces of slivers and hull simplices are listed near their clipped power face instead of in
 * their whole reach box. The bound must be conservative, so:
 *  - on random ball sets (negative weights, several t) the scan over the index equals the skin
 *    function from its definition (skin_oracle.h, long double, every subset of <= 4 balls)
 *    wherever that is <= 0 and is never below it; the hull simplices are the clipped ones
 *    there;
 *  - wherever the walk locates x in the mixed cell of a clipped simplex X (its own tests: z* in
 *    X and v in nu_X by the link half-spaces; independent of the clip) and x lies in X's reach
 *    box, x lies in the box the index lists X in (skin_listed_box), on random sets and on B* of
 *    the unit cube (eps 0.5; its regular triangulation has slivers by construction);
 *  - on B* of the cube the scan with the clip equals the scan without it (skin_clip_off)
 *    wherever either is <= 0, while the index holds fewer registrations. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "fl_test.h"
#include "skin_cube.h"
#include "skin_rng.h"
#include "skin/skin_internal.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "skin_oracle.h"
#pragma GCC diagnostic pop

static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;

static double rnd(void)
{
    return skin_rng_next(&rng_state);
}

static size_t count_clipped(const fl_skin_function *g)
{
    size_t n = 0;
    for (size_t i = 0; i < g->simplex_count; i++)
        n += g->simplex[i].box_exact == SKIN_BOX_CLIPPED;
    return n;
}

/* x in the located cell's reach box but outside the box the index lists it in: 1 (a bug). */
static int outside_listed(const fl_skin_function *g, uint32_t cell, const double *x)
{
    const skin_simplex *s = &g->simplex[cell];
    double a[3], e[3][3], rlo[3], rhi[3], lo[3], hi[3];
    double r = SKIN_REACH_MARGIN * skin_reach(g->balls, s, g->t);
    if (!(r > 0)) return 0;
    skin_frame(g->balls, s, a, e);
    for (int c = 0; c < 3; c++) {
        rlo[c] = rhi[c] = a[c];
        for (int j = 0; j < s->k; j++) {
            rlo[c] = fmin(rlo[c], a[c] + e[j][c]);
            rhi[c] = fmax(rhi[c], a[c] + e[j][c]);
        }
        /* strictly inside the reach box, away from its rounding */
        if (!(x[c] > rlo[c] - r * (1 - 1e-9) && x[c] < rhi[c] + r * (1 - 1e-9))) return 0;
    }
    if (!skin_listed_box(g, s, lo, hi)) return 1;
    for (int c = 0; c < 3; c++)
        if (!(x[c] >= lo[c] && x[c] <= hi[c])) return 1;
    return 0;
}

static void test_random_sets_scan_equals_definition(void)
{
    enum { N = 20, Q = 300 };
    static const double ts[3] = {0.5, 0.3, 0.8};
    double b[4 * N];
    size_t clipped = 0;
    int located_clipped = 0, negatives = 0;
    for (int round = 0; round < 6; round++) {
        double t = ts[round % 3];
        for (int i = 0; i < N; i++) {
            for (int c = 0; c < 3; c++)
                b[4 * i + c] = 4 * rnd();
            double r = 0.4 + 0.8 * rnd();
            b[4 * i + 3] = i % 4 == 3 ? -0.3 * r * r : r * r;
        }
        fl_skin_function *g = NULL;
        fl_error err;
        CHECK_STATUS(fl_skin_function_new(b, N, t, &g, &err), FL_OK, &err);
        if (!g) continue;
        clipped += count_clipped(g);
        uint32_t start = 0;
        int bad = 0;
        for (int q = 0; q < Q; q++) {
            double x[3];
            for (int c = 0; c < 3; c++)
                x[c] = -0.5 + 5 * rnd();
            double want = (double)skin_oracle_value(b, N, t, x);
            double got = skin_value_scan(g, x), tol = 1e-9 * (1 + fabs(want));
            negatives += want < 0;
            int ok = want <= 0 ? fabs(got - want) <= tol : got >= want - tol;
            if (!ok && bad++ < 3)
                CHECK_MSG(0, "t %g: scan %.17g, definition %.17g at (%.17g, %.17g, %.17g)", t,
                          got, want, x[0], x[1], x[2]);
            double w;
            int why = 0;
            uint32_t cell = skin_locate_why(g, x, &start, &w, &why);
            if (why == 0 && cell != SKIN_NO_CELL &&
                g->simplex[cell].box_exact == SKIN_BOX_CLIPPED) {
                located_clipped++;
                CHECK_MSG(!outside_listed(g, cell, x), "t %g: x (%.17g, %.17g, %.17g) in cell %u "
                          "but outside its listed box", t, x[0], x[1], x[2], cell);
            }
        }
        CHECK_MSG(bad == 0, "t %g: %d of %d scan values differ from the definition", t, bad, Q);
        fl_skin_function_free(g);
    }
    /* the hull simplices (unbounded power faces) are the clipped ones on these sets */
    CHECK_MSG(clipped > 50 && located_clipped > 100 && negatives > 150,
              "%zu clipped simplices, %d points located in them, %d negative", clipped,
              located_clipped, negatives);
}

static size_t registrations(const fl_skin_function *g)
{
    return g->cell_start[g->dims[0] * g->dims[1] * g->dims[2]];
}

static void test_cube_bstar_clip_is_conservative(void)
{
    fl_skin_approx a;
    fl_error err;
    CHECK_STATUS(skin_cube_bstar(0.5, &a, &err), FL_OK, &err);
    const double *b = a.star.xyzw;
    size_t n = a.star.count;
    fl_skin_function *g = NULL, *plain = NULL;
    CHECK_STATUS(skin_function_new_mesher(b, n, 0.5, &g, &err), FL_OK, &err);
    skin_clip_off = 1;
    CHECK_STATUS(skin_function_new_mesher(b, n, 0.5, &plain, &err), FL_OK, &err);
    skin_clip_off = 0;
    if (!g || !plain) {
        fl_skin_function_free(g);
        fl_skin_function_free(plain);
        fl_skin_approx_free(&a);
        return;
    }
    size_t clipped = count_clipped(g), sliver_clipped = 0;
    for (size_t i = 0; i < g->simplex_count; i++)
        sliver_clipped += g->simplex[i].box_exact == SKIN_BOX_CLIPPED &&
                          (g->simplex[i].shaky & SKIN_SHAKY_SLIVER);
    CHECK_MSG(count_clipped(plain) == 0, "clip off: %zu clipped", count_clipped(plain));
    CHECK_MSG(sliver_clipped > 100, "cube B*: %zu clipped, %zu of them faces of slivers", clipped,
              sliver_clipped);
    size_t npos = 0, *pos = malloc(n * sizeof *pos);
    for (size_t i = 0; i < n; i++)
        if (b[4 * i + 3] > 0) pos[npos++] = i;
    uint32_t start = 0;
    double x[3] = {0, 0, 0};
    int bad = 0, negatives = 0, located_clipped = 0, q_count = 6000;
    for (int q = 0; q < q_count && npos; q++) {
        const double *c = b + 4 * pos[(size_t)(rnd() * (double)npos)];
        double r = sqrt(c[3]);
        for (int k = 0; k < 3; k++)
            x[k] = q % 40 == 0 ? c[k] + r * (2 * rnd() - 1) : x[k] + 0.05 * r * (2 * rnd() - 1);
        double s = skin_value_scan(g, x), p = skin_value_scan(plain, x);
        negatives += p < 0;
        int ok = s <= 0 || p <= 0 ? fabs(s - p) <= 1e-9 * (1 + fabs(p)) : 1;
        if (!ok && bad++ < 3)
            CHECK_MSG(0, "at (%.17g, %.17g, %.17g): scan %.17g, without the clip %.17g", x[0],
                      x[1], x[2], s, p);
        double w;
        int why = 0;
        uint32_t cell = skin_locate_why(g, x, &start, &w, &why);
        if (why == 0 && cell != SKIN_NO_CELL && g->simplex[cell].box_exact == SKIN_BOX_CLIPPED) {
            located_clipped++;
            CHECK_MSG(!outside_listed(g, cell, x), "x (%.17g, %.17g, %.17g) in cell %u but "
                      "outside its listed box", x[0], x[1], x[2], cell);
        }
    }
    CHECK_MSG(bad == 0, "%d of %d scans differ with the clip", bad, q_count);
    CHECK_MSG(negatives > q_count / 10 && located_clipped > q_count / 20,
              "%d negative, %d located in clipped cells", negatives, located_clipped);
    size_t rc = registrations(g), rp = registrations(plain);
    CHECK_MSG(rc < rp, "registrations %zu with the clip, %zu without", rc, rp);
    printf("cube B* (%zu balls): %zu simplices, %zu clipped (%zu faces of slivers); "
           "registrations %zu -> %zu; %d of %d points located in clipped cells\n",
           n, g->simplex_count, clipped, sliver_clipped, rp, rc, located_clipped, q_count);
    free(pos);
    fl_skin_function_free(g);
    fl_skin_function_free(plain);
    fl_skin_approx_free(&a);
}

FL_TEST_MAIN(FL_TEST_CASE(test_random_sets_scan_equals_definition),
             FL_TEST_CASE(test_cube_bstar_clip_is_conservative))

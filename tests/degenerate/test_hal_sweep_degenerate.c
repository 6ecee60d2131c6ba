/* Degenerate inputs for HAL 2D (build + point inclusion) and the sweep hierarchy (build +
 * closest point). Expected outcomes: specific errors for short rings, NaN/Inf and out-of-range
 * coordinates; for rings with repeated or collinear vertices, self-intersecting (bow-tie) and
 * fully collinear rings, the inclusion answers equal the brute-force even-odd test with exact
 * predicates; for degenerate triangles (a point, a segment, a nearly collinear sliver) and
 * repeated-point polylines, the closest distance equals a brute-force long-double oracle. */
#include "degen.h"
#include "hal/hal2_oracle.h"
#include "sweep/sweep_oracle.h"

static void expect_hal_matches_oracle(const char *name, fl_polygon *p)
{
    fl_hal2 hal;
    fl_error err;
    fl_status st = fl_hal2_build(p, NULL, &hal, &err);
    CHECK_MSG(st == FL_OK, "%s: %s", name, err.message);
    if (st != FL_OK) return;
    /* Queries: a 17x17 lattice over the bounding box (hits vertices and edges), each vertex. */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t v = 0; v < p->vertex_count; v++)
        for (int c = 0; c < 2; c++)
            lo[c] = fmin(lo[c], p->xy[2 * v + c]), hi[c] = fmax(hi[c], p->xy[2 * v + c]);
    for (int i = -1; i <= 17; i++)
        for (int j = -1; j <= 17; j++) {
            double q[2] = {lo[0] + (hi[0] - lo[0]) * i / 16, lo[1] + (hi[1] - lo[1]) * j / 16};
            uint8_t w;
            CHECK_STATUS(fl_hal2_contains(&hal, q, 1, &w, &err), FL_OK, &err);
            CHECK_MSG(w == oracle_where(p, q), "%s: (%g, %g) hal %d oracle %d", name, q[0], q[1],
                      w, oracle_where(p, q));
        }
    fl_hal2_free(&hal);
}

static void one_ring(fl_polygon *p, double *xy, size_t n, size_t *rs, size_t *ps)
{
    rs[0] = 0, rs[1] = n, ps[0] = 0, ps[1] = 1;
    *p = (fl_polygon){n, xy, 1, rs, 1, ps};
}

static void test_hal2_degenerate(void)
{
    size_t rs[2], ps[2];
    fl_polygon p;
    fl_hal2 hal;
    fl_error err;
    double two[] = {0, 0, 1, 1};
    one_ring(&p, two, 2, rs, ps);
    CHECK_FAILS(fl_hal2_build(&p, NULL, &hal, &err), &err, FL_ERR_INPUT, "fewer than 3");
    double nan_[] = {0, 0, 1, 0, NAN, 1};
    one_ring(&p, nan_, 3, rs, ps);
    CHECK_FAILS(fl_hal2_build(&p, NULL, &hal, &err), &err, FL_ERR_INPUT, "not finite");
    double inf_[] = {0, 0, 1, 0, 0, -INFINITY};
    one_ring(&p, inf_, 3, rs, ps);
    CHECK_FAILS(fl_hal2_build(&p, NULL, &hal, &err), &err, FL_ERR_INPUT, "not finite");
    double repeated[] = {0, 0, 0, 0, 4, 0, 4, 0, 4, 0, 4, 4, 0, 4, 0, 4, 0, 0};
    one_ring(&p, repeated, 9, rs, ps);
    expect_hal_matches_oracle("repeated vertices", &p);
    double collinear_run[] = {0, 0, 1, 0, 2, 0, 3, 0, 4, 0, 4, 4, 2, 4, 0, 4, 0, 2};
    one_ring(&p, collinear_run, 9, rs, ps);
    expect_hal_matches_oracle("collinear vertices", &p);
    double flat[] = {0, 0, 1, 1, 2, 2, 3, 3, 1, 1};
    one_ring(&p, flat, 5, rs, ps);
    expect_hal_matches_oracle("all on one line", &p);
    double bowtie[] = {0, 0, 4, 4, 4, 0, 0, 4};
    one_ring(&p, bowtie, 4, rs, ps);
    expect_hal_matches_oracle("bow-tie", &p);
    double huge[] = {-1e300, -1e300, 1e300, -1e300, 1e300, 1e300, 0, 1e-300, -1e300, 1e300};
    one_ring(&p, huge, 5, rs, ps);
    expect_hal_matches_oracle("1e300 with a 1e-300 dent", &p);
    /* A NaN query is rejected. */
    one_ring(&p, bowtie, 4, rs, ps);
    CHECK_STATUS(fl_hal2_build(&p, NULL, &hal, &err), FL_OK, &err);
    double q[] = {1, 1, NAN, 0};
    uint8_t w[2];
    CHECK_FAILS(fl_hal2_contains(&hal, q, 2, w, &err), &err, FL_ERR_INPUT, "");
    fl_hal2_free(&hal);
}

/* Regression (found by fuzz/fuzz_hal2.c): a vertex 1e-100 from its neighbour made the width
 * of the disc through it cancel catastrophically; the level-0 certified error (2.59) was then
 * smaller than the distance of vertex (0,-6) to the approximation (3.09). Every level's
 * certified error must bound the deviation of every original vertex. */
static void test_hal2_certified_error_near_duplicate(void)
{
    static const double ys[] = {7.5118002732592141e-306, 1e-300, 1e-100, 1e-10, 0, -1e-3};
    for (size_t i = 0; i < sizeof ys / sizeof *ys; i++) {
        double xy[] = {0, -6, 1, 0, 2, 0, 3, 0, 3, ys[i], -8, -8};
        size_t rs[2], ps[2];
        fl_polygon p;
        one_ring(&p, xy, 6, rs, ps);
        fl_hal2 hal;
        fl_error err;
        CHECK_STATUS(fl_hal2_build(&p, NULL, &hal, &err), FL_OK, &err);
        for (uint32_t level = 0; level <= hal.depth; level++) {
            fl_polygon a;
            double bound;
            CHECK_STATUS(fl_hal2_approximate_level(&hal, level, &a, &bound, &err), FL_OK, &err);
            double dev = oracle_deviation(&p, &a);
            CHECK_MSG(dev <= bound * (1 + 1e-9), "y %g level %u: deviation %.17g > certified "
                      "%.17g", ys[i], level, dev, bound);
            fl_polygon_free(&a);
        }
        fl_hal2_free(&hal);
    }
}

/* A vertex at 1e308 overflows the disc widths to NaN (found by fuzz/fuzz_hal2.c in CI: the NaN
 * comparison picked the missing side's vertex, the tree grew past its node array). The build
 * must fall back to plain discs; every vertex and the inclusion answers stay exact. */
static void test_hal2_overflowing_coordinates(void)
{
    double xy[] = {-1.125, -1.125, -7.125, -1.75, -8, 1.4821969375237396e-323, 7.75, 1e308};
    size_t rs[2], ps[2];
    fl_polygon p;
    one_ring(&p, xy, 4, rs, ps);
    fl_hal2 hal;
    fl_error err;
    CHECK_STATUS(fl_hal2_build(&p, NULL, &hal, &err), FL_OK, &err);
    CHECK_MSG(hal.node_count <= p.vertex_count, "%zu nodes for %zu vertices",
              (size_t)hal.node_count, p.vertex_count);
    double q[][2] = {{-1.125, -1.125}, {7.75, 1e308}, {-4, 0}, {0, 0}, {-100, 0}, {5, 5e307}};
    for (size_t k = 0; k < sizeof q / sizeof *q; k++) {
        uint8_t w;
        CHECK_STATUS(fl_hal2_contains(&hal, q[k], 1, &w, &err), FL_OK, &err);
        CHECK_MSG(w == oracle_where(&p, q[k]), "(%g, %g): hal %d oracle %d", q[k][0], q[k][1], w,
                  oracle_where(&p, q[k]));
    }
    fl_hal2_free(&hal);
}

static void expect_sweep(const char *name, fl_mesh *m, const double *q, size_t nq)
{
    fl_sweep *s;
    fl_error err;
    fl_status st = fl_sweep_build(m, NULL, &s, &err);
    CHECK_MSG(st == FL_OK, "%s: %s", name, err.message);
    if (st != FL_OK) return;
    for (size_t k = 0; k < nq; k++) {
        ld best = INFINITY;
        for (size_t t = 0; t < m->triangle_count; t++) {
            ld d = oracle_mesh_element(m->xyz, m->tri, t, q + 3 * k);
            if (d < best) best = d;
        }
        for (int tol = 0; tol < 2; tol++) {
            fl_closest r;
            CHECK_STATUS(fl_sweep_closest(s, q + 3 * k, 1, tol ? 0.25 : 0, &r, &err), FL_OK, &err);
            CHECK_MSG(r.lower <= (double)best + 1e-9 && (double)best <= r.upper + 1e-9,
                      "%s query %zu tol %d: [%.17g, %.17g] misses %.17Lg", name, k, tol, r.lower,
                      r.upper, best);
        }
    }
    fl_sweep_free(s);
}

static void test_sweep_degenerate(void)
{
    fl_sweep *s;
    fl_error err;
    double v[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    uint32_t t[] = {0, 1, 2};
    fl_mesh empty = {3, v, 0, t};
    CHECK_FAILS(fl_sweep_build(&empty, NULL, &s, &err), &err, FL_ERR_INPUT, "no triangles");
    fl_mesh oob = {2, v, 1, t};
    CHECK_FAILS(fl_sweep_build(&oob, NULL, &s, &err), &err, FL_ERR_INPUT, "refers to vertex 2");
    double big[] = {0, 0, 0, 1e151, 0, 0, 0, 1, 0};
    fl_mesh bigm = {3, big, 1, t};
    CHECK_FAILS(fl_sweep_build(&bigm, NULL, &s, &err), &err, FL_ERR_INPUT, "beyond 1e150");
    double nanv[] = {0, 0, 0, 1, NAN, 0, 0, 1, 0};
    fl_mesh nanm = {3, nanv, 1, t};
    CHECK_FAILS(fl_sweep_build(&nanm, NULL, &s, &err), &err, FL_ERR_INPUT, "not finite");
    double line[] = {0, 0, 1, 1};
    CHECK_FAILS(fl_sweep_polyline_build(line, 1, 2, 0, NULL, &s, &err), &err, FL_ERR_INPUT,
                "at least 2");
    /* Regression (found by fuzz/fuzz_sweep.c): a point triangle and a segment triangle; the
     * root's bounding triangle was a sliver whose distance came out far too large, so the
     * tolerance answer's interval [lower, upper] had lower > upper and missed the distance. */
    double pv[] = {0, 7.125, -5, -4.375, -8, -8, -8, -8, -8, -8, -8, -8};
    uint32_t pt[] = {0, 0, 0, 0, 0, 1};
    fl_mesh pm = {4, pv, 2, pt};
    double q[] = {1, 1, -8, 0, 7.125, -5, -3, -3, -3, 100, 0, 0};
    expect_sweep("point + segment triangles", &pm, q, 4);
    /* Every triangle degenerate along one line, repeated faces, duplicate vertices. */
    double lv[] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 1, 1, 1};
    uint32_t lt[] = {0, 1, 2, 1, 2, 3, 0, 3, 1, 0, 1, 2, 4, 4, 3, 2, 4, 0};
    fl_mesh lm = {5, lv, 6, lt};
    expect_sweep("collinear triangles", &lm, q, 4);
    /* A sliver 1e-13 off a line and a grid of coplanar triangles. */
    double sv[] = {0, 0, 0, 10, 0, 0, 5, 1e-13, 0, 0, 0, 1, 10, 0, 1};
    uint32_t st_[] = {0, 1, 2, 0, 1, 3, 1, 4, 3};
    fl_mesh sm = {5, sv, 3, st_};
    expect_sweep("sliver", &sm, q, 4);
    /* Regression (fuzz_sweep, then MemorySanitizer): vertices spread 16 units one way and
     * 1e-291 the other; every candidate bounding triangle overflowed, the root's triangle
     * was left uninitialized and a tolerance query returned lower 3e69 > upper 14.4. */
    double tv[] = {-7.875, 0, 4, 0, -8, 7, -8, -8, 3.6075033944888133e-291,
                   0, 4.9406564584124654e-324, -7.25, -8, 4, -8, -8, -7, -8};
    uint32_t tt[] = {0, 0, 0, 0, 0, 3};
    fl_mesh tm = {6, tv, 2, tt};
    double q8[] = {-8, -8, -8, 0, 0, 0, 1e3, -1e3, 5};
    expect_sweep("thin spread", &tm, q8, 3);
    /* A sliver 1e-300 wide seen from 8 units away (fuzz_sweep: the oracle had called its
     * projection inside; the distance is to an edge, 12.32). */
    double fv[] = {2e-300, 2e-300, 2e-300, 2e-300, 9.8813129168249309e-324, 2e-300,
                   2e-300, -1.375, -1.375};
    uint32_t ft[] = {1, 2, 0};
    fl_mesh fm = {3, fv, 1, ft};
    expect_sweep("1e-300 sliver", &fm, q8, 3);
    /* A polyline of repeated points only. */
    double rep[] = {1, 2, 1, 2, 1, 2};
    CHECK_STATUS(fl_sweep_polyline_build(rep, 3, 2, 1, NULL, &s, &err), FL_OK, &err);
    fl_closest r;
    double q2[] = {4, 6};
    CHECK_STATUS(fl_sweep_closest(s, q2, 1, 0, &r, &err), FL_OK, &err);
    CHECK_NEAR(r.distance, 5.0, 1e-12);
    fl_sweep_free(s);
}

int main(void)
{
    fl_test_case cases[] = {
        FL_TEST_CASE(test_hal2_degenerate),
        FL_TEST_CASE(test_hal2_certified_error_near_duplicate),
        FL_TEST_CASE(test_hal2_overflowing_coordinates),
        FL_TEST_CASE(test_sweep_degenerate),
    };
    return fl_test_run(cases, sizeof cases / sizeof *cases);
}

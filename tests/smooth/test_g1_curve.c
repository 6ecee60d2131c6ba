/* Properties of the G1 cubic Bézier curves of thesis §9.2, on the demo leaf and on random
 * star-shaped polygons, for the three tangent weightings. */
#include "fl_test.h"

static fl_polygon star_polygon(unsigned long long seed, size_t n)
{
    fl_polygon p = {n, malloc(2 * n * sizeof(double)), 1, malloc(2 * sizeof(size_t)),
                    1, malloc(2 * sizeof(size_t))};
    for (size_t i = 0; i < n; i++) {
        double a = 6.283185307179586 * ((double)i + 0.8 * fl_test_rand01(&seed)) / (double)n;
        double r = 0.3 + fl_test_rand01(&seed);
        p.xy[2 * i] = r * cos(a);
        p.xy[2 * i + 1] = r * sin(a);
    }
    p.ring_start[0] = p.polygon_start[0] = 0;
    p.ring_start[1] = n;
    p.polygon_start[1] = 1;
    return p;
}

/* Interpolation (bitwise), closedness and tangent continuity at every joint: P'(1) of the
 * segment ending at a vertex and Q'(0) of the one starting there are parallel and point the
 * same way. */
static void check_curve(const fl_polygon *p, int weighting, size_t *repairs)
{
    fl_g1_curve c;
    fl_error err;
    fl_g1_curve_options o = {.weighting = weighting};
    CHECK_STATUS(fl_g1_curve_build(p, &o, &c, &err), FL_OK, &err);
    *repairs += c.orientation_repairs;
    for (size_t r = 0; r < p->ring_count; r++) {
        size_t lo = p->ring_start[r], hi = p->ring_start[r + 1];
        for (size_t i = lo; i < hi; i++) {
            size_t prev = i > lo ? i - 1 : hi - 1, next = i + 1 < hi ? i + 1 : lo;
            double a[2], b[2], da[2], db[2];
            fl_g1_curve_eval(&c, i, 0, a, db);
            fl_g1_curve_eval(&c, prev, 1, b, da);
            CHECK(a[0] == p->xy[2 * i] && a[1] == p->xy[2 * i + 1]);
            CHECK(b[0] == p->xy[2 * i] && b[1] == p->xy[2 * i + 1]);
            CHECK(c.ctrl[8 * i + 6] == p->xy[2 * next] && c.ctrl[8 * i + 7] == p->xy[2 * next + 1]);
            double cross = da[0] * db[1] - da[1] * db[0], dot = da[0] * db[0] + da[1] * db[1];
            double na = hypot(da[0], da[1]), nb = hypot(db[0], db[1]);
            CHECK_MSG(fabs(cross) <= 1e-12 * na * nb && dot > 0, "vertex %zu: cross %g dot %g", i,
                      cross / (na * nb), dot);
        }
    }
    fl_polygon s;
    CHECK_STATUS(fl_g1_curve_sample(&c, 8, &s, &err), FL_OK, &err);
    CHECK_EQ_INT(s.vertex_count, 8 * p->vertex_count);
    CHECK_EQ_INT(s.ring_count, p->ring_count);
    fl_polygon_free(&s);
    fl_g1_curve_free(&c);
}

static void test_g1_curves_interpolate_and_are_tangent_continuous(void)
{
    fl_polygon leaf;
    fl_error err;
    CHECK_STATUS(fl_read_polygon(FL_SOURCE_DIR "/data/demo/leaf.xy", &leaf, &err), FL_OK, &err);
    size_t repairs = 0;
    for (int w = 0; w <= 3; w++)
        check_curve(&leaf, w, &repairs);
    fl_polygon_free(&leaf);
    for (unsigned long long seed = 1; seed <= 50; seed++) {
        fl_polygon p = star_polygon(seed, 5 + seed % 40);
        for (int w = 0; w <= 3; w++)
            check_curve(&p, w, &repairs);
        fl_polygon_free(&p);
    }
}

static void test_g1_curve_repairs_a_tangent_that_folds_the_curve(void)
{
    /* At (1, 0) the length-weighted tangent is along v2 - v0 = (-11, 1): it projects v0 ahead
     * of the vertex, so P'(1) and Q'(0) would be opposite (a cusp). */
    double xy[] = {0, 0, 1, 0, -10, 1, -10, -3};
    size_t rs[] = {0, 4}, ps[] = {0, 1};
    fl_polygon p = {4, xy, 1, rs, 1, ps};
    size_t repairs = 0;
    check_curve(&p, FL_G1_WEIGHT_SIZE, &repairs);
    CHECK(repairs >= 1);
    /* the uniform weighting never needs a repair (margin 1 + cos of the turn angle) */
    repairs = 0;
    check_curve(&p, FL_G1_WEIGHT_UNIFORM, &repairs);
    CHECK_EQ_INT(repairs, 0);
}

static void test_g1_curve_rejects_bad_rings(void)
{
    fl_g1_curve c;
    fl_error err;
    size_t rs[] = {0, 3}, ps[] = {0, 1};
    double spike[] = {0, 0, 1, 0, 0.5, 0}; /* turns back by 180 degrees at (1, 0) */
    fl_polygon p = {3, spike, 1, rs, 1, ps};
    CHECK_STATUS(fl_g1_curve_build(&p, NULL, &c, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "turns back") != NULL);
    double dup[] = {0, 0, 1, 0, 1, 0};
    p.xy = dup;
    CHECK_STATUS(fl_g1_curve_build(&p, NULL, &c, &err), FL_ERR_INPUT, &err);
    double nan[] = {0, 0, 1, 0, NAN, 1};
    p.xy = nan;
    CHECK_STATUS(fl_g1_curve_build(&p, NULL, &c, &err), FL_ERR_INPUT, &err);
    size_t rs2[] = {0, 2};
    p.ring_start = rs2;
    p.vertex_count = 2;
    p.xy = spike;
    CHECK_STATUS(fl_g1_curve_build(&p, NULL, &c, &err), FL_ERR_INPUT, &err);
    CHECK(c.ctrl == NULL && c.vertex_count == 0);
}

static void test_g1_curve_svg_has_one_cubic_a_segment(void)
{
    fl_polygon p = star_polygon(9, 12);
    fl_g1_curve c;
    fl_error err;
    CHECK_STATUS(fl_g1_curve_build(&p, NULL, &c, &err), FL_OK, &err);
    CHECK_STATUS(fl_g1_curve_write_svg("g1_curve_test.svg", &c, &err), FL_OK, &err);
    FILE *f = fopen("g1_curve_test.svg", "r");
    int cubics = 0, ch;
    while (f && (ch = fgetc(f)) != EOF)
        cubics += ch == 'C';
    if (f) fclose(f);
    CHECK_EQ_INT(cubics, 12);
    remove("g1_curve_test.svg");
    fl_g1_curve_free(&c);
    fl_polygon_free(&p);
}

FL_TEST_MAIN(FL_TEST_CASE(test_g1_curves_interpolate_and_are_tangent_continuous),
             FL_TEST_CASE(test_g1_curve_repairs_a_tangent_that_folds_the_curve),
             FL_TEST_CASE(test_g1_curve_rejects_bad_rings),
             FL_TEST_CASE(test_g1_curve_svg_has_one_cubic_a_segment))

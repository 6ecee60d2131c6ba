/* fl_polygon_check on polygons with known answers, and its edge-intersection count against a
 * brute-force count with the independent GMP segment oracle. */
#include "fl_test.h"
#include "gmp_oracle.h"

/* A polygon from rings given as point lists; ring_len lists the rings, polygon_len the number
 * of rings of each polygon. */
static fl_polygon make_polygon(const double *xy, const size_t *ring_len, size_t rings,
                               const size_t *polygon_len, size_t polygons)
{
    fl_polygon p;
    p.ring_count = rings;
    p.polygon_count = polygons;
    p.ring_start = calloc(rings + 1, sizeof(size_t));
    p.polygon_start = calloc(polygons + 1, sizeof(size_t));
    for (size_t r = 0; r < rings; r++)
        p.ring_start[r + 1] = p.ring_start[r] + ring_len[r];
    for (size_t q = 0; q < polygons; q++)
        p.polygon_start[q + 1] = p.polygon_start[q] + polygon_len[q];
    p.vertex_count = p.ring_start[rings];
    p.xy = malloc((p.vertex_count ? p.vertex_count : 1) * 2 * sizeof(double));
    memcpy(p.xy, xy, p.vertex_count * 2 * sizeof(double));
    return p;
}

static fl_polygon_report check(const fl_polygon *p)
{
    fl_polygon_report r;
    fl_error err;
    CHECK_STATUS(fl_polygon_check(p, &r, &err), FL_OK, &err);
    return r;
}

static void test_ccw_square_is_simple_with_area_1(void)
{
    static const double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
    fl_polygon p = make_polygon(xy, (size_t[]){4}, 1, (size_t[]){1}, 1);
    fl_polygon_report r = check(&p);
    CHECK(r.simple);
    CHECK_EQ_INT(r.edge_intersections, 0);
    CHECK_EQ_INT(r.ring_orientation[0], 1);
    CHECK_EQ_INT(r.orientation, 1);
    CHECK_NEAR(r.area, 1.0, 0);
    CHECK_NEAR(r.ring_area[0], 1.0, 0);
    CHECK_EQ_INT(r.holes, 0);
    fl_polygon_report_free(&r);
    fl_polygon_free(&p);
}

static void test_cw_square_is_clockwise(void)
{
    static const double xy[] = {0, 0, 0, 1, 1, 1, 1, 0};
    fl_polygon p = make_polygon(xy, (size_t[]){4}, 1, (size_t[]){1}, 1);
    fl_polygon_report r = check(&p);
    CHECK(r.simple);
    CHECK_EQ_INT(r.ring_orientation[0], -1);
    CHECK_EQ_INT(r.orientation, -1);
    CHECK_NEAR(r.ring_area[0], -1.0, 0);
    CHECK_NEAR(r.area, 1.0, 0);
    fl_polygon_report_free(&r);
    fl_polygon_free(&p);
}

static void test_bow_tie_is_not_simple(void)
{
    static const double xy[] = {0, 0, 1, 1, 1, 0, 0, 1};
    fl_polygon p = make_polygon(xy, (size_t[]){4}, 1, (size_t[]){1}, 1);
    fl_polygon_report r = check(&p);
    CHECK(!r.simple);
    CHECK_EQ_INT(r.edge_intersections, 1);
    CHECK(r.first_crossing[0] == 0 && r.first_crossing[1] == 2);
    CHECK_EQ_INT(r.holes_inside, -1);
    fl_polygon_report_free(&r);
    fl_polygon_free(&p);
}

static void test_square_with_hole_inside(void)
{
    static const double xy[] = {0, 0, 4, 0, 4, 4, 0, 4, /* hole, clockwise */ 1,
                                1, 1, 2, 2, 2, 2, 1};
    fl_polygon p = make_polygon(xy, (size_t[]){4, 4}, 2, (size_t[]){2}, 1);
    fl_polygon_report r = check(&p);
    CHECK(r.simple);
    CHECK_EQ_INT(r.holes, 1);
    CHECK_EQ_INT(r.ring_orientation[1], -1);
    CHECK_EQ_INT(r.orientation, 1);
    CHECK_NEAR(r.area, 15.0, 0);
    CHECK_EQ_INT(r.holes_inside, 1);
    fl_polygon_report_free(&r);
    fl_polygon_free(&p);
    /* the same hole moved outside; then one crossing the boundary */
    static const double out[] = {0, 0, 4, 0, 4, 4, 0, 4, 5, 1, 5, 2, 6, 2, 6, 1};
    p = make_polygon(out, (size_t[]){4, 4}, 2, (size_t[]){2}, 1);
    r = check(&p);
    CHECK(r.simple);
    CHECK_EQ_INT(r.holes_inside, 0);
    fl_polygon_report_free(&r);
    fl_polygon_free(&p);
    static const double cross[] = {0, 0, 4, 0, 4, 4, 0, 4, 3, 1, 3, 2, 5, 2, 5, 1};
    p = make_polygon(cross, (size_t[]){4, 4}, 2, (size_t[]){2}, 1);
    r = check(&p);
    CHECK(!r.simple);
    CHECK_EQ_INT(r.edge_intersections, 2);
    fl_polygon_report_free(&r);
    fl_polygon_free(&p);
}

static void test_spike_folding_back_is_not_simple(void)
{
    /* (2,0) -> (3,0) -> (1,0): consecutive edges overlap beyond their shared vertex */
    static const double xy[] = {0, 0, 2, 0, 3, 0, 1, 0, 1, 1};
    fl_polygon p = make_polygon(xy, (size_t[]){5}, 1, (size_t[]){1}, 1);
    fl_polygon_report r = check(&p);
    CHECK(!r.simple);
    fl_polygon_report_free(&r);
    fl_polygon_free(&p);
    static const double dup[] = {0, 0, 1, 0, 1, 0, 1, 1};
    p = make_polygon(dup, (size_t[]){4}, 1, (size_t[]){1}, 1);
    r = check(&p);
    CHECK(!r.simple); /* repeated consecutive vertex */
    fl_polygon_report_free(&r);
    fl_polygon_free(&p);
}

/* A comb: a base strip [0,T]x[0,1] with T triangular teeth of height 2 on top, walked
 * counter-clockwise; 2T + 3 vertices, area 2T. */
static void test_comb_with_ten_thousand_vertices(void)
{
    size_t teeth = 5000, k = 0;
    double *xy = malloc(2 * (2 * teeth + 3) * sizeof(double));
    xy[2 * k] = 0, xy[2 * k + 1] = 0, k++;
    xy[2 * k] = (double)teeth, xy[2 * k + 1] = 0, k++;
    for (size_t i = teeth; i-- > 0;) {
        xy[2 * k] = (double)i + 1, xy[2 * k + 1] = 1, k++;
        xy[2 * k] = (double)i + 0.5, xy[2 * k + 1] = 3, k++;
    }
    xy[2 * k] = 0, xy[2 * k + 1] = 1, k++;
    fl_polygon p = make_polygon(xy, (size_t[]){k}, 1, (size_t[]){1}, 1);
    fl_polygon_report r = check(&p);
    CHECK_EQ_INT(r.vertices, 10003);
    CHECK(r.simple);
    CHECK_EQ_INT(r.ring_orientation[0], 1);
    CHECK_NEAR(r.area, 2.0 * (double)teeth, 1e-9);
    fl_polygon_report_free(&r);
    fl_polygon_free(&p);
    free(xy);
}

/* Random rings on a small grid: the count of improperly meeting edge pairs equals a brute
 * force over all pairs with the GMP oracle (consecutive edges: overlap beyond the common
 * vertex, i.e. the far end of one lies on the other). */
static void test_random_rings_edge_count_matches_oracle(void)
{
    unsigned long long rng = 31;
    for (int trial = 0; trial < 40; trial++) {
        size_t len[2] = {3 + fl_test_rand_u64(&rng) % 8, 3 + fl_test_rand_u64(&rng) % 8};
        size_t n = len[0] + len[1];
        double xy[64];
        for (size_t i = 0; i < 2 * n; i++)
            xy[i] = (double)(fl_test_rand_u64(&rng) % 5);
        fl_polygon p = make_polygon(xy, len, 2, (size_t[]){1, 1}, 2);
        fl_polygon_report r = check(&p);
        size_t expect = 0;
        for (size_t e = 0; e < n; e++)
            for (size_t f = e + 1; f < n; f++) {
                size_t re = e >= len[0], rf = f >= len[0], s0 = re ? len[0] : 0,
                       s1 = rf ? len[0] : 0;
                size_t e1 = e + 1 == s0 + len[re] ? s0 : e + 1,
                       f1 = f + 1 == s1 + len[rf] ? s1 : f + 1;
                const double *a = xy + 2 * e, *b = xy + 2 * e1, *c = xy + 2 * f, *d = xy + 2 * f1;
                if (re == rf && (e1 == f || f1 == e)) {
                    /* consecutive: shared vertex w, far ends u (of one) and v (of the other) */
                    const double *u = e1 == f ? a : c, *w = e1 == f ? b : a, *v = e1 == f ? d : b;
                    int degenerate =
                        (u[0] == w[0] && u[1] == w[1]) || (v[0] == w[0] && v[1] == w[1]);
                    if (!degenerate)
                        expect +=
                            (size_t)(oracle_segments2(w, u, v, v) || oracle_segments2(w, v, u, u));
                } else {
                    expect += (size_t)oracle_segments2(a, b, c, d);
                }
            }
        CHECK_EQ_INT(r.edge_intersections, expect);
        fl_polygon_report_free(&r);
        fl_polygon_free(&p);
    }
}

static void test_bad_ring_ranges_are_rejected(void)
{
    static const double xy[] = {0, 0, 1, 0, 1, 1};
    fl_polygon p = make_polygon(xy, (size_t[]){3}, 1, (size_t[]){1}, 1);
    p.ring_start[1] = 4;
    fl_polygon_report r;
    fl_error err;
    CHECK_STATUS(fl_polygon_check(&p, &r, &err), FL_ERR_INPUT, &err);
    CHECK(r.ring_orientation == NULL);
    p.ring_start[1] = 3;
    p.xy[3] = INFINITY;
    CHECK_STATUS(fl_polygon_check(&p, &r, &err), FL_ERR_INPUT, &err);
    fl_polygon_free(&p);
}

static void test_empty_polygon_is_simple_with_zero_area(void)
{
    fl_polygon p = {0, NULL, 0, NULL, 0, NULL};
    fl_polygon_report r = check(&p);
    CHECK(r.simple);
    CHECK_EQ_INT(r.rings, 0);
    CHECK_NEAR(r.area, 0.0, 0);
    fl_polygon_report_free(&r);
}

FL_TEST_MAIN(FL_TEST_CASE(test_empty_polygon_is_simple_with_zero_area),
             FL_TEST_CASE(test_ccw_square_is_simple_with_area_1),
             FL_TEST_CASE(test_cw_square_is_clockwise), FL_TEST_CASE(test_bow_tie_is_not_simple),
             FL_TEST_CASE(test_square_with_hole_inside),
             FL_TEST_CASE(test_spike_folding_back_is_not_simple),
             FL_TEST_CASE(test_comb_with_ten_thousand_vertices),
             FL_TEST_CASE(test_random_rings_edge_count_matches_oracle),
             FL_TEST_CASE(test_bad_ring_ranges_are_rejected))

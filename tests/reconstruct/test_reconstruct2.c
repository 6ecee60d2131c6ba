/* 2D boundary construction by constriction (thesis §5.2, Algorithm 5.1): well-sampled closed
 * curves come back in their own order; degenerate inputs give valid polygons or clear errors. */
#include "recon2_test_util.h"

static void reconstruct_ok(const double *xy, size_t n, const fl_reconstruct2_options *opt,
                           fl_reconstruction2 *rec)
{
    fl_error err;
    CHECK_STATUS(fl_reconstruct2(xy, n, opt, rec, &err), FL_OK, &err);
    if (rec->boundary) rt_check_valid(xy, rec);
}

static void test_points_on_a_circle_give_the_hull_in_order(void)
{
    size_t n = 200;
    double *xy = rt_star(n, 0, 0);
    fl_reconstruction2 rec;
    reconstruct_ok(xy, n, NULL, &rec);
    CHECK(rt_is_input_order(&rec, n));
    CHECK(rec.all_on_boundary);
    CHECK(isnan(rec.augmented_c0));
    fl_reconstruction2_free(&rec);
    free(xy);
}

static void test_dense_star_is_reconstructed_in_sampling_order(void)
{
    for (int lobes = 3; lobes <= 7; lobes += 2) {
        size_t n = 400;
        double *xy = rt_star(n, lobes, 0.35);
        fl_reconstruction2 rec;
        reconstruct_ok(xy, n, NULL, &rec);
        CHECK_MSG(rt_is_input_order(&rec, n), "lobes %d", lobes);
        CHECK(rec.all_on_boundary);
        fl_reconstruction2_free(&rec);
        free(xy);
    }
}

/* A thick letter "C" (an annular sector, inner radius 0.6, outer 1, mouth 2 x 1.2 rad wide), its
 * sides sampled finer than a tenth of the band width. The mouth must be wide enough for the
 * inner arc to be "sensed from outside" (§5.2); for a narrow mouth the γ-indicator digs through
 * the band instead, the curled case of §5.6 / Fig. 5.9. */
static double *letter_c(size_t *n_out)
{
    size_t outer = 160, inner = 100, cap = 8, n = outer + inner + 2 * cap, j = 0;
    double a0 = 1.2, a1 = 2 * RT_PI - 1.2, *xy = malloc(2 * n * sizeof *xy);
    for (size_t i = 0; i < outer; i++, j++) { /* outer arc, counterclockwise */
        double t = a0 + (a1 - a0) * (double)i / (double)(outer - 1);
        xy[2 * j] = cos(t), xy[2 * j + 1] = sin(t);
    }
    for (size_t i = 1; i <= cap; i++, j++) { /* end cap at a1, outward to inward */
        double r = 1 - 0.4 * (double)i / (double)(cap + 1);
        xy[2 * j] = r * cos(a1), xy[2 * j + 1] = r * sin(a1);
    }
    for (size_t i = 0; i < inner; i++, j++) { /* inner arc, clockwise */
        double t = a1 - (a1 - a0) * (double)i / (double)(inner - 1);
        xy[2 * j] = 0.6 * cos(t), xy[2 * j + 1] = 0.6 * sin(t);
    }
    for (size_t i = 1; i <= cap; i++, j++) {
        double r = 0.6 + 0.4 * (double)i / (double)(cap + 1);
        xy[2 * j] = r * cos(a0), xy[2 * j + 1] = r * sin(a0);
    }
    *n_out = n;
    return xy;
}

static void test_letter_c_is_reconstructed_in_sampling_order(void)
{
    size_t n;
    double *xy = letter_c(&n);
    fl_reconstruction2 rec;
    reconstruct_ok(xy, n, NULL, &rec);
    CHECK(rt_is_input_order(&rec, n));
    CHECK(rec.all_on_boundary);
    fl_reconstruction2_free(&rec);
    free(xy);
}

/* A spiral band of width 0.4 between r = 1 + t/2π and r + 0.4 for t in [0, 3π] (the arms are
 * 0.6 apart), sampled along its whole boundary including the two end caps. */
static void test_spiral_band_is_reconstructed_in_sampling_order(void)
{
    size_t m = 400, cap = 12, n = 2 * m + 2 * cap, j = 0;
    double *xy = malloc(2 * n * sizeof *xy), end = 3 * RT_PI;
    for (size_t i = 0; i < m; i++, j++) { /* outer side, outward */
        double t = end * (double)i / (double)(m - 1), r = 1.4 + t / (2 * RT_PI);
        xy[2 * j] = r * cos(t), xy[2 * j + 1] = r * sin(t);
    }
    for (size_t i = 1; i <= cap; i++, j++) {
        double r = 1.4 + end / (2 * RT_PI) - 0.4 * (double)i / (double)(cap + 1);
        xy[2 * j] = r * cos(end), xy[2 * j + 1] = r * sin(end);
    }
    for (size_t i = 0; i < m; i++, j++) { /* inner side, back inward */
        double t = end * (double)(m - 1 - i) / (double)(m - 1), r = 1 + t / (2 * RT_PI);
        xy[2 * j] = r * cos(t), xy[2 * j + 1] = r * sin(t);
    }
    for (size_t i = 1; i <= cap; i++, j++) {
        xy[2 * j] = 1 + 0.4 * (double)i / (double)(cap + 1), xy[2 * j + 1] = 0;
    }
    fl_reconstruction2 rec;
    reconstruct_ok(xy, n, NULL, &rec);
    CHECK(rec.all_on_boundary);
    CHECK(rt_is_input_order(&rec, n));
    fl_reconstruction2_free(&rec);
    free(xy);
}

/* An L-shaped polygon sampled along its sides: long collinear runs on every side. */
static void test_collinear_sides_of_an_l_shape_are_kept_in_order(void)
{
    const double corners[] = {0, 0, 4, 0, 4, 1, 1, 1, 1, 4, 0, 4};
    size_t n;
    double *xy = rt_polygon(corners, 6, 5, &n);
    fl_reconstruction2 rec;
    reconstruct_ok(xy, n, NULL, &rec);
    CHECK(rec.all_on_boundary);
    CHECK(rt_is_input_order(&rec, n));
    fl_reconstruction2_free(&rec);
    free(xy);
}

static void test_duplicates_share_the_place_of_their_first_copy(void)
{
    size_t m = 150, n = 2 * m;
    double *star = rt_star(m, 5, 0.3), *xy = malloc(2 * n * sizeof *xy);
    memcpy(xy, star, 2 * m * sizeof *xy);
    for (size_t i = 0; i < m; i++) { /* copies in reverse order after the originals */
        xy[2 * (m + i)] = star[2 * (m - 1 - i)];
        xy[2 * (m + i) + 1] = star[2 * (m - 1 - i) + 1];
    }
    fl_reconstruction2 rec;
    reconstruct_ok(xy, n, NULL, &rec);
    CHECK_EQ_INT(rec.point_count, n);
    CHECK_EQ_INT(rec.unique_count, m);
    CHECK(rec.all_on_boundary);
    CHECK(rt_is_input_order(&rec, m));
    fl_reconstruction2_free(&rec);
    free(star);
    free(xy);
}

static void test_grid_points_give_a_simple_polygon_through_all(void)
{
    for (size_t k = 3; k <= 12; k += 3) {
        size_t n = k * k;
        double *xy = malloc(2 * n * sizeof *xy);
        for (size_t i = 0; i < n; i++)
            xy[2 * i] = (double)(i % k), xy[2 * i + 1] = (double)(i / k);
        fl_reconstruction2 rec;
        reconstruct_ok(xy, n, NULL, &rec);
        CHECK_MSG(rec.all_on_boundary, "%zux%zu grid: %s", k, k, rec.reason);
        fl_reconstruction2_free(&rec);
        free(xy);
    }
}

/* A long boundary (20000 shuffled samples of a five-lobed star: the polygon is listed by the
 * segmented walk, order2.c, and constriction runs on the internal numbering): the polygon must
 * be the sampling order, starting at a hull vertex, its area the shoelace sum of the input
 * coordinates in that order, and the Delaunay triangles handed back exactly those fl_dt2_build
 * gives for the same input (the internal numbering is mapped back). */
static void test_long_shuffled_curve_comes_back_in_order_with_its_delaunay(void)
{
    size_t n = 20000;
    double *star = rt_star(n, 5, 0.3), *xy = malloc(2 * n * sizeof *xy);
    uint32_t *pos = malloc(n * sizeof *pos); /* pos[i]: place on the curve of input point i */
    for (size_t i = 0; i < n; i++)
        pos[i] = (uint32_t)i;
    uint64_t x = 0x853c49e6748fea9bull;
    for (size_t i = n - 1; i > 0; i--) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        size_t j = (size_t)(x % (i + 1));
        uint32_t t = pos[i];
        pos[i] = pos[j], pos[j] = t;
    }
    for (size_t i = 0; i < n; i++)
        xy[2 * i] = star[2 * pos[i]], xy[2 * i + 1] = star[2 * pos[i] + 1];
    fl_reconstruction2 rec;
    reconstruct_ok(xy, n, NULL, &rec);
    CHECK_EQ_INT(rec.boundary_count, n);
    size_t out_of_order = 0;
    double area2 = 0;
    for (size_t i = 0; i < rec.boundary_count; i++) {
        uint32_t v = rec.boundary[i], w = rec.boundary[(i + 1) % rec.boundary_count];
        out_of_order += pos[w] != (pos[v] + 1) % n;
        area2 += xy[2 * v] * xy[2 * w + 1] - xy[2 * v + 1] * xy[2 * w];
    }
    CHECK_EQ_INT(out_of_order, 0);
    CHECK(rec.area == area2 / 2);
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, n, NULL, &dt, &err), FL_OK, &err);
    CHECK_EQ_INT(rec.delaunay_count, dt.triangle_count);
    CHECK(rec.delaunay_tri &&
          memcmp(rec.delaunay_tri, dt.tri, 3 * dt.triangle_count * sizeof *dt.tri) == 0);
    CHECK_EQ_INT(rec.boundary[0], dt.hull[0]);
    fl_dt2_free(&dt);
    fl_reconstruction2_free(&rec);
    free(pos);
    free(xy);
    free(star);
}

static void test_three_points_give_their_triangle(void)
{
    const double xy[] = {0, 0, 0, 1, 1, 0}; /* clockwise as given */
    fl_reconstruction2 rec;
    reconstruct_ok(xy, 3, NULL, &rec);
    CHECK_EQ_INT(rec.boundary_count, 3);
    CHECK_EQ_INT(rec.triangle_count, 1);
    CHECK_NEAR(rec.area, 0.5, 0);
    CHECK(rec.all_on_boundary);
    fl_reconstruction2_free(&rec);
}

static void test_bad_input_is_rejected_with_the_right_status(void)
{
    fl_reconstruction2 rec;
    fl_error err;
    const double two[] = {0, 0, 1, 1, 0, 0}, line[] = {0, 0, 1, 1, 2, 2, 3, 3};
    const double nan_xy[] = {0, 0, 1, 0, NAN, 1};
    CHECK_STATUS(fl_reconstruct2(two, 3, NULL, &rec, &err), FL_ERR_INPUT, &err);
    CHECK(rec.boundary == NULL);
    CHECK_STATUS(fl_reconstruct2(line, 4, NULL, &rec, &err), FL_ERR_ALGORITHM, &err);
    CHECK_STATUS(fl_reconstruct2(nan_xy, 3, NULL, &rec, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_reconstruct2(NULL, 3, NULL, &rec, &err), FL_ERR_USAGE, &err);
    fl_reconstruct2_options opt = {0};
    opt.criterion = (fl_reconstruct2_criterion)7;
    CHECK_STATUS(fl_reconstruct2(line, 4, &opt, &rec, &err), FL_ERR_USAGE, &err);
    fl_reconstruction2_free(&rec);
    fl_reconstruction2_free(&rec); /* freeing twice is a no-op */
}

FL_TEST_MAIN(FL_TEST_CASE(test_points_on_a_circle_give_the_hull_in_order),
             FL_TEST_CASE(test_dense_star_is_reconstructed_in_sampling_order),
             FL_TEST_CASE(test_letter_c_is_reconstructed_in_sampling_order),
             FL_TEST_CASE(test_spiral_band_is_reconstructed_in_sampling_order),
             FL_TEST_CASE(test_collinear_sides_of_an_l_shape_are_kept_in_order),
             FL_TEST_CASE(test_duplicates_share_the_place_of_their_first_copy),
             FL_TEST_CASE(test_grid_points_give_a_simple_polygon_through_all),
             FL_TEST_CASE(test_long_shuffled_curve_comes_back_in_order_with_its_delaunay),
             FL_TEST_CASE(test_three_points_give_their_triangle),
             FL_TEST_CASE(test_bad_input_is_rejected_with_the_right_status))

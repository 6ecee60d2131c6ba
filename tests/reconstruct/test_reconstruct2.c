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
             FL_TEST_CASE(test_three_points_give_their_triangle),
             FL_TEST_CASE(test_bad_input_is_rejected_with_the_right_status))

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

FL_TEST_MAIN(FL_TEST_CASE(test_points_on_a_circle_give_the_hull_in_order),
             FL_TEST_CASE(test_dense_star_is_reconstructed_in_sampling_order))

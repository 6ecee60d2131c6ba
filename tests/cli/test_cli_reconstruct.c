/* `flintstone reconstruct` end to end: a well-sampled closed curve comes back in its own order
 * (thesis §5.6), impossible input exits 3, malformed constraints exit 2. */
#include <math.h>

#include "cli_run.h"
#include "fl_test.h"

static cli_result r;

/* data/demo/leaf.xy samples (1.4 r(t) cos t, r(t) sin t) with r > 0 at increasing t, shuffled.
 * The curve is star-shaped around the origin, so its true cyclic order is the order of the
 * polar angle: a correct reconstruction visits the angles with exactly one wrap-around. */
static void test_reconstruct_leaf_recovers_the_curve_order(void)
{
    CHECK_EQ_INT(
        cli_run(&r, "reconstruct '" FL_SOURCE_DIR "/data/demo/leaf.xy' --json -o rec_leaf.xy"), 0);
    CHECK(strstr(r.out, "\"all_on_boundary\":true") != NULL);
    CHECK(strstr(r.out, "\"boundary_vertices\":160") != NULL);
    fl_polygon poly;
    fl_error err;
    CHECK_STATUS(fl_read_polygon("rec_leaf.xy", &poly, &err), FL_OK, &err);
    if (poly.vertex_count == 160) {
        int wraps = 0;
        for (size_t i = 0; i < 160; i++) {
            size_t j = (i + 1) % 160;
            double a = atan2(poly.xy[2 * i + 1], poly.xy[2 * i]);
            double b = atan2(poly.xy[2 * j + 1], poly.xy[2 * j]);
            wraps += b < a; /* counterclockwise: angles increase except at the one wrap */
        }
        CHECK_EQ_INT(wraps, 1);
    } else {
        CHECK_EQ_INT(poly.vertex_count, 160);
    }
    fl_polygon_free(&poly);
    remove("rec_leaf.xy");
}

static void test_reconstruct_collinear_points_exit_3(void)
{
    cli_write_file("rec_line.xy", "0 0\n1 0\n2 0\n3 0\n");
    CHECK_EQ_INT(cli_run(&r, "reconstruct rec_line.xy"), 3);
    CHECK(strstr(r.err, "collinear") != NULL);
    remove("rec_line.xy");
}

static void test_reconstruct_bad_kept_edges_exit_2(void)
{
    cli_write_file("rec_sq.xy", "0 0\n2 0\n2 2\n0 2\n1 1.2\n");
    cli_write_file("rec_keep.txt", "0 9\n");
    CHECK_EQ_INT(cli_run(&r, "reconstruct rec_sq.xy --keep rec_keep.txt"), 2);
    cli_write_file("rec_keep.txt", "0 1.5\n");
    CHECK_EQ_INT(cli_run(&r, "reconstruct rec_sq.xy --keep rec_keep.txt"), 2);
    CHECK(strstr(r.err, "rec_keep.txt:1:") != NULL);
    /* A kept diagonal through the square's inside is honoured: the boundary uses it. */
    cli_write_file("rec_keep.txt", "0 4\n");
    CHECK_EQ_INT(cli_run(&r, "reconstruct rec_sq.xy --keep rec_keep.txt --json"), 0);
    CHECK(strstr(r.out, "\"all_on_boundary\":true") != NULL);
    remove("rec_keep.txt");
    remove("rec_sq.xy");
}

FL_TEST_MAIN(FL_TEST_CASE(test_reconstruct_leaf_recovers_the_curve_order),
             FL_TEST_CASE(test_reconstruct_collinear_points_exit_3),
             FL_TEST_CASE(test_reconstruct_bad_kept_edges_exit_2))

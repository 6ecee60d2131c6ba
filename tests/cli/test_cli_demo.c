/* The README's first command runs `flintstone demo`: it must complete and record every step. */
#include "cli_run.h"
#include "fl_test.h"

static cli_result r;

static void test_demo_writes_summary_with_every_step_valid(void)
{
    CHECK_EQ_INT(cli_run(&r, "demo --out demo_test_out --quiet"), 0);
    char summary[65536];
    cli_read_file("demo_test_out/summary.json", summary, sizeof summary);
    CHECK(summary[0] == '{');
    CHECK(strstr(summary, "\"check\":{") != NULL);
    CHECK(strstr(summary, "\"genus\":1") != NULL); /* the bundled torus */
    CHECK(strstr(summary, "\"delaunay_2d\":{") != NULL);
    CHECK(strstr(summary, "\"delaunay_3d\":{") != NULL);
    CHECK(strstr(summary, "\"reconstruct_2d\":{") != NULL);
    CHECK(strstr(summary, "\"all_on_boundary\":true") != NULL);
    CHECK(strstr(summary, "\"valid\":false") == NULL);
    FILE *f = fopen("demo_test_out/peanut-delaunay.vtk", "r");
    CHECK(f != NULL);
    if (f) fclose(f);
    CHECK_EQ_INT(system("rm -rf demo_test_out"), 0);
}

static void test_demo_with_missing_data_fails_without_summary(void)
{
    CHECK_EQ_INT(cli_run(&r, "demo --data no-such-dir --out demo_test_missing"), 4);
    CHECK(strstr(r.err, "no-such-dir") != NULL);
    FILE *f = fopen("demo_test_missing/summary.json", "r");
    CHECK(f == NULL);
    if (f) fclose(f);
    CHECK_EQ_INT(system("rm -rf demo_test_missing"), 0);
}

FL_TEST_MAIN(FL_TEST_CASE(test_demo_writes_summary_with_every_step_valid),
             FL_TEST_CASE(test_demo_with_missing_data_fails_without_summary))

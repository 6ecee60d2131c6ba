/* `flintstone hausdorff` against distances known in closed form, and its error contract. */
#include <math.h>

#include "cli_run.h"
#include "fl_test.h"

static cli_result r;

/* Reads the JSON array "key":[lo,hi] from the output. */
static int json_interval(const char *out, const char *key, double *lo, double *hi)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\":[", key);
    const char *p = strstr(out, pat);
    return p && sscanf(p + strlen(pat), "%lf,%lf", lo, hi) == 2;
}

/* Two unit squares 0.25 apart, shifted by 0.1 in x (A: 2 triangles, B: 4 triangles):
 * h = sqrt(0.1^2 + 0.25^2) both ways, reached on the edges x = 0 of A and x = 1.1 of B. */
static void test_hausdorff_of_shifted_squares_matches_closed_form(void)
{
    cli_write_file("hd_a.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
    cli_write_file("hd_b.off", "OFF\n5 4 0\n0.1 0 0.25\n1.1 0 0.25\n1.1 1 0.25\n0.1 1 0.25\n"
                               "0.6 0.5 0.25\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n");
    CHECK_EQ_INT(cli_run(&r, "hausdorff hd_a.off hd_b.off --precision 1e-8 --both --json "
                             "-o hd_field.ply"),
                 0);
    double h = sqrt(0.01 + 0.0625), lo, hi;
    CHECK(json_interval(r.out, "hausdorff", &lo, &hi));
    CHECK_MSG(lo <= h + 1e-13 && h <= hi + 1e-13 && hi - lo <= 1e-8, "[%.17g, %.17g]", lo, hi);
    CHECK(json_interval(r.out, "h_ab", &lo, &hi) && lo <= h + 1e-13 && h <= hi + 1e-13);
    CHECK(json_interval(r.out, "h_ba", &lo, &hi) && lo <= h + 1e-13 && h <= hi + 1e-13);
    CHECK(strstr(r.out, "\"where\":[[") != NULL);
    CHECK(strstr(r.out, "\"samples\":") != NULL && strstr(r.out, "\"seconds\":") != NULL);
    char ply[65536];
    cli_read_file("hd_field.ply", ply, sizeof ply);
    CHECK(strncmp(ply, "ply\n", 4) == 0 && strstr(ply, "property uchar red") != NULL);
    remove("hd_field.ply");
    remove("hd_a.off");
    remove("hd_b.off");
}

/* 2D polylines (.xy, --closed): a unit square against the same square scaled by 2 about its
 * centre: every point of the big square is 0.5 from the small one at most, its corners are
 * sqrt(0.5) from the small square's corners: h = sqrt(0.5). */
static void test_hausdorff_of_polygons(void)
{
    cli_write_file("hd_s.xy", "0 0\n1 0\n1 1\n0 1\n");
    cli_write_file("hd_l.xy", "-0.5 -0.5\n1.5 -0.5\n1.5 1.5\n-0.5 1.5\n");
    CHECK_EQ_INT(cli_run(&r, "hausdorff hd_s.xy hd_l.xy --closed --precision 1e-9 --json"), 0);
    double lo, hi, h = sqrt(0.5);
    CHECK(json_interval(r.out, "hausdorff", &lo, &hi));
    CHECK_MSG(lo <= h + 1e-13 && h <= hi + 1e-13 && hi - lo <= 1e-9, "[%.17g, %.17g]", lo, hi);
    CHECK(strstr(r.out, "\"where_on\":\"b\"") != NULL);
    remove("hd_s.xy");
    remove("hd_l.xy");
}

/* Usage errors exit 1, bad files 2 or 4; --help prints an example. */
static void test_hausdorff_errors_and_help(void)
{
    CHECK_EQ_INT(cli_run(&r, "hausdorff --help"), 0);
    CHECK(strstr(r.out, "example:") != NULL);
    CHECK_EQ_INT(cli_run(&r, "hausdorff only_one.off"), 1);
    CHECK_EQ_INT(cli_run(&r, "hausdorff a.off b.off --precision 1 --relative 1"), 1);
    CHECK_EQ_INT(cli_run(&r, "hausdorff a.off b.off --budget -3"), 1);
    CHECK_EQ_INT(cli_run(&r, "hausdorff a.off b.xy"), 1);
    CHECK_EQ_INT(cli_run(&r, "hausdorff a.off b.off -o field.csv"), 1);
    CHECK_EQ_INT(cli_run(&r, "hausdorff hd_missing_a.off hd_missing_b.off"), 4);
    cli_write_file("hd_bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n");
    int code = cli_run(&r, "hausdorff hd_bad.off hd_bad.off");
    CHECK_MSG(code == 2, "exit %d: %s", code, r.err);
    remove("hd_bad.off");
}

FL_TEST_MAIN(FL_TEST_CASE(test_hausdorff_of_shifted_squares_matches_closed_form),
             FL_TEST_CASE(test_hausdorff_of_polygons), FL_TEST_CASE(test_hausdorff_errors_and_help))

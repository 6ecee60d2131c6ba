/* The README's first command runs `flintstone demo`: it must complete and record every step. */
#include "cli_run.h"
#include "fl_test.h"

static cli_result r;

/* The number after "key": in the text following `from` (NaN when absent). */
static double number_after(const char *text, const char *from, const char *key)
{
    const char *p = strstr(text, from);
    if (!p) return NAN;
    char k[128];
    snprintf(k, sizeof k, "\"%s\":", key);
    p = strstr(p, k);
    return p ? atof(p + strlen(k)) : NAN;
}

static void test_demo_writes_summary_and_report_with_every_step_valid(void)
{
    CHECK_EQ_INT(cli_run(&r, "demo --out demo_test_out --quiet"), 0);
    static char summary[1 << 16];
    cli_read_file("demo_test_out/summary.json", summary, sizeof summary);
    CHECK(summary[0] == '{');
    static const char *steps[] = {
        "\"leaf\":{",         "\"delaunay_2d\":{", "\"reconstruct_2d\":{", "\"hal_2d\":{",
        "\"inside_2d\":{",    "\"hausdorff_2d\":{", "\"smooth_2d\":{",     "\"peanut\":{",
        "\"reconstruct_3d\":{", "\"check\":{",       "\"hal_3d\":{",        "\"hausdorff_3d\":{",
        "\"smooth_3d\":{",    "\"skin\":{",         "\"torus\":{"};
    for (size_t i = 0; i < sizeof steps / sizeof steps[0]; i++)
        CHECK_MSG(strstr(summary, steps[i]) != NULL, "step %s missing", steps[i]);
    CHECK(strstr(summary, "\"error\":\"") == NULL); /* a failed step */
    CHECK(strstr(summary, "\"all_on_boundary\":false") == NULL);
    CHECK(strstr(summary, "\"closed\":false") == NULL);
    CHECK(strstr(summary, "\"valid\":false") == NULL);
    CHECK(strstr(summary, "\"self_intersections\":0") != NULL);
    /* The torus keeps its handle (so the 3D flintstone tree, which needs genus 0, is skipped
     * there with its reason); the peanut's reconstruction is a sphere. */
    CHECK_EQ_INT(number_after(summary, "\"torus\":{", "genus"), 1);
    CHECK(strstr(strstr(summary, "\"torus\":{"), "\"hal_3d\":{\"skipped\"") != NULL);
    CHECK_EQ_INT(number_after(summary, "\"peanut\":{", "genus"), 0);
    /* Certified Hausdorff intervals: lower <= upper; the leaf polygon is within a few
     * hundredths of the true curve (160 points on a curve of length ~8), and its G1 curve too. */
    const char *h2 = strstr(summary, "\"hausdorff_2d\":{");
    double l2 = NAN, u2 = NAN;
    if (h2) sscanf(strstr(h2, "\"hausdorff\":[") + 13, "%lf,%lf", &l2, &u2);
    CHECK_MSG(l2 <= u2 && u2 < 0.05, "curve <-> polygon [%g, %g]", l2, u2);
    CHECK(number_after(summary, "\"smooth_2d\":{", "hausdorff_to_truth") < 0.05);
    const char *h3 = strstr(summary, "\"hausdorff_3d\":{");
    double l3 = NAN, u3 = NAN;
    if (h3) sscanf(strstr(h3, "\"h_ab\":[") + 8, "%lf,%lf", &l3, &u3);
    CHECK_MSG(l3 <= u3 && u3 < 0.3, "reference -> ours [%g, %g]", l3, u3);
    /* G1: the torus's smooth surface interpolates its vertices and has no kinks. */
    CHECK(number_after(summary, "\"torus\":{", "max_vertex_error") < 1e-12);
    CHECK(number_after(summary, "\"torus\":{", "max_edge_normal_jump_deg") < 1e-6);
    /* The grid estimate of the leaf's area agrees with the polygon's exact area. */
    double area = number_after(summary, "\"reconstruct_2d\":{", "area");
    CHECK_NEAR(number_after(summary, "\"inside_2d\":{", "area_estimate"), area, 0.02 * area);
    static char html[1 << 20];
    cli_read_file("demo_test_out/report.html", html, sizeof html);
    CHECK(strncmp(html, "<!DOCTYPE html>", 15) == 0);
    CHECK(strstr(html, "</html>") != NULL);
    CHECK(strstr(html, "flintstone reconstruct") != NULL);
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

static void test_report_on_user_mesh_and_points_runs_the_steps_that_apply(void)
{
    static char summary[1 << 16];
    CHECK_EQ_INT(cli_run(&r, "report " FL_SOURCE_DIR "/data/demo/torus.off --out rep_mesh --quiet"),
                 0);
    cli_read_file("rep_mesh/summary.json", summary, sizeof summary);
    CHECK(strstr(summary, "\"torus\":{") != NULL);
    CHECK(strstr(summary, "\"reconstruct_3d\"") == NULL); /* a mesh skips reconstruction */
    CHECK_EQ_INT(number_after(summary, "\"check\":{", "genus"), 1);
    CHECK_EQ_INT(cli_run(&r, "report " FL_SOURCE_DIR "/data/demo/leaf.xy --truth " FL_SOURCE_DIR
                             "/data/demo/leaf-truth.xy --out rep_pts --json"),
                 0);
    CHECK(strstr(r.out, "\"ok\":true") != NULL);
    cli_read_file("rep_pts/summary.json", summary, sizeof summary);
    CHECK(strstr(summary, "\"leaf\":{") != NULL);
    CHECK(strstr(summary, "\"hausdorff_2d\":{") != NULL);
    CHECK_EQ_INT(system("rm -rf rep_mesh rep_pts"), 0);
}

static void test_report_on_missing_or_bad_input_fails_cleanly(void)
{
    CHECK_EQ_INT(cli_run(&r, "report no-such-file.xyz --out rep_missing"), 4);
    CHECK(strstr(r.err, "no-such-file.xyz") != NULL);
    FILE *f = fopen("rep_missing/summary.json", "r");
    CHECK(f == NULL);
    if (f) fclose(f);
    CHECK_EQ_INT(cli_run(&r, "report"), 1);
    cli_write_file("rep_bad.xyz", "0 0 0\n1 nan 0\n0 1 0\n0 0 1\n");
    /* The report is still written, saying what failed; the exit code is the failure's. */
    CHECK_EQ_INT(cli_run(&r, "report rep_bad.xyz --out rep_bad --quiet"), 2);
    static char html[1 << 16];
    cli_read_file("rep_bad/report.html", html, sizeof html);
    CHECK(strstr(html, "failed") != NULL);
    CHECK_EQ_INT(system("rm -rf rep_missing rep_bad rep_bad.xyz"), 0);
}

FL_TEST_MAIN(FL_TEST_CASE(test_demo_writes_summary_and_report_with_every_step_valid),
             FL_TEST_CASE(test_demo_with_missing_data_fails_without_summary),
             FL_TEST_CASE(test_report_on_user_mesh_and_points_runs_the_steps_that_apply),
             FL_TEST_CASE(test_report_on_missing_or_bad_input_fails_cleanly))

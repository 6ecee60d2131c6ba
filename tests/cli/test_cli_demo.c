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
    static const char *steps[] = {"\"leaf\":{",        "\"delaunay_2d\":{", "\"reconstruct_2d\":{",
                                  "\"hal_2d\":{",      "\"inside_2d\":{",   "\"distance_2d\":{",
                                  "\"peanut\":{",      "\"reconstruct_3d\":{", "\"check\":{",
                                  "\"distance_3d\":{", "\"torus\":{"};
    for (size_t i = 0; i < sizeof steps / sizeof steps[0]; i++)
        CHECK_MSG(strstr(summary, steps[i]) != NULL, "step %s missing", steps[i]);
    CHECK(strstr(summary, "\"error\":\"") == NULL); /* a failed step */
    CHECK(strstr(summary, "\"all_on_boundary\":false") == NULL);
    CHECK(strstr(summary, "\"closed\":false") == NULL);
    CHECK(strstr(summary, "\"valid\":false") == NULL);
    CHECK(strstr(summary, "\"self_intersections\":0") != NULL);
    /* The torus keeps its handle; the peanut's reconstruction is a sphere. */
    CHECK_EQ_INT(number_after(summary, "\"torus\":{", "genus"), 1);
    CHECK_EQ_INT(number_after(summary, "\"peanut\":{", "genus"), 0);
    /* The leaf points lie on the true curve, 160 of them on a curve of length ~8: the polygon
     * is within a few hundredths of it. The peanut: 1500 points on area ~13, spacing ~0.1. */
    CHECK(number_after(summary, "\"distance_2d\":{", "truth_to_boundary") < 0.05);
    CHECK(number_after(summary, "\"distance_2d\":{", "boundary_to_truth") < 1e-3);
    CHECK(number_after(summary, "\"distance_3d\":{", "truth_to_mesh") < 0.3);
    CHECK(number_after(summary, "\"distance_3d\":{", "mesh_to_truth") < 0.05);
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

FL_TEST_MAIN(FL_TEST_CASE(test_demo_writes_summary_and_report_with_every_step_valid),
             FL_TEST_CASE(test_demo_with_missing_data_fails_without_summary))

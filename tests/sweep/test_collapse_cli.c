/* `flintstone closest --hierarchy collapse` against distances known in closed form, and its
 * refusals (polylines, --k / --within, unknown hierarchies). */
#include <math.h>

#include "../cli/cli_run.h"
#include "fl_test.h"

static cli_result r;

/* The octahedron |x| + |y| + |z| = 1 (closed, 8 faces; every edge collapse would break it, so
 * it is its own base mesh) and a 4x4 grid of the unit square at z = 0 (open, simplified). A
 * point (a, a, a) with a > 1/3 is (3a - 1)/sqrt(3) from the octahedron; points above the
 * square are at their height. */
static void test_collapse_cli_closed_form(void)
{
    cli_write_file("cc_oct.off", "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                                 "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n"
                                 "3 3 1 5\n3 0 3 5\n");
    cli_write_file("cc_q.xyz", "1 1 1\n0.5 0.5 0.5\n");
    CHECK_EQ_INT(cli_run(&r, "closest cc_oct.off cc_q.xyz --hierarchy collapse -o cc_o.csv"), 0);
    double expect[2] = {2 / sqrt(3.0), 0.5 / sqrt(3.0)}, d;
    char csv[4096], *line;
    cli_read_file("cc_o.csv", csv, sizeof csv);
    line = strchr(csv, '\n');
    for (int i = 0; i < 2 && line; i++, line = strchr(line + 1, '\n')) {
        CHECK(sscanf(line + 1, "%*d,%lf", &d) == 1);
        CHECK_NEAR(d, expect[i], 1e-15);
    }
    char off[8192] = "OFF\n25 32 0\n";
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++)
            snprintf(off + strlen(off), sizeof off - strlen(off), "%g %g 0\n", i / 4.0, j / 4.0);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            int a = 5 * i + j, b = a + 5;
            snprintf(off + strlen(off), sizeof off - strlen(off), "3 %d %d %d\n3 %d %d %d\n", a, b,
                     b + 1, a, b + 1, a + 1);
        }
    cli_write_file("cc_grid.off", off);
    cli_write_file("cc_q2.xyz", "0.3 0.7 0.25\n0.9 0.1 -2\n");
    CHECK_EQ_INT(cli_run(&r, "closest cc_grid.off cc_q2.xyz --hierarchy collapse --json"), 0);
    CHECK(strstr(r.out, "\"elements\":32") != NULL);
    CHECK(strstr(r.out, "\"max_distance\":2,") != NULL);
    CHECK(strstr(r.out, "\"mean_distance\":1.125,") != NULL);
    remove("cc_oct.off");
    remove("cc_q.xyz");
    remove("cc_o.csv");
    remove("cc_grid.off");
    remove("cc_q2.xyz");
}

static void test_collapse_cli_refusals(void)
{
    cli_write_file("cc_line.xy", "0 0\n1 0\n1 1\n");
    cli_write_file("cc_p.xy", "0.5 0.5\n");
    CHECK(cli_run(&r, "closest cc_line.xy cc_p.xy --hierarchy collapse") != 0);
    CHECK(strstr(r.err, "triangle mesh") != NULL);
    CHECK(cli_run(&r, "closest cc_line.xy cc_p.xy --hierarchy octree") != 0);
    CHECK(cli_run(&r, "closest cc_line.xy cc_p.xy --hierarchy collapse --k 2") != 0);
    CHECK_EQ_INT(cli_run(&r, "closest --help"), 0);
    CHECK(strstr(r.out, "--hierarchy") != NULL);
    remove("cc_line.xy");
    remove("cc_p.xy");
}

FL_TEST_MAIN(FL_TEST_CASE(test_collapse_cli_closed_form), FL_TEST_CASE(test_collapse_cli_refusals))

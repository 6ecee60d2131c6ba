/* `flintstone closest --hierarchy collapse` against distances known in closed form, and its
 * refusals (polylines, unknown hierarchies); --k / --within through it give the same rows as
 * the spatial hierarchy. */
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

/* The k-nearest and within rows of both hierarchies on a 6x6 grid with a bump agree: the same
 * distances in the same order (elements may differ only between equidistant triangles). */
static void test_collapse_cli_neighbours(void)
{
    char off[16384] = "OFF\n36 50 0\n";
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 6; j++)
            snprintf(off + strlen(off), sizeof off - strlen(off), "%g %g %g\n", i / 5.0, j / 5.0,
                     0.1 * sin(3.0 * i + 2.0 * j));
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++) {
            int a = 6 * i + j, b = a + 6;
            snprintf(off + strlen(off), sizeof off - strlen(off), "3 %d %d %d\n3 %d %d %d\n", a, b,
                     b + 1, a, b + 1, a + 1);
        }
    cli_write_file("cc_g6.off", off);
    cli_write_file("cc_q6.xyz", "0.3 0.7 0.25\n0.9 0.1 -0.5\n0.31 0.69 0.2\n");
    const char *opts[2] = {"--k 7", "--within 0.3"};
    for (int o = 0; o < 2; o++) {
        char cmd[256], a[8192], b[8192];
        snprintf(cmd, sizeof cmd, "closest cc_g6.off cc_q6.xyz %s -o cc_s.csv", opts[o]);
        CHECK_EQ_INT(cli_run(&r, cmd), 0);
        snprintf(cmd, sizeof cmd, "closest cc_g6.off cc_q6.xyz %s --hierarchy collapse -o cc_c.csv",
                 opts[o]);
        CHECK_EQ_INT(cli_run(&r, cmd), 0);
        cli_read_file("cc_s.csv", a, sizeof a);
        cli_read_file("cc_c.csv", b, sizeof b);
        char *la = strchr(a, '\n'), *lb = strchr(b, '\n');
        int rows = 0;
        for (; la && lb && la[1] && lb[1]; la = strchr(la + 1, '\n'), lb = strchr(lb + 1, '\n')) {
            unsigned qa, ra, qb, rb;
            double da, db;
            CHECK(sscanf(la + 1, "%u,%u,%*u,%lf", &qa, &ra, &da) == 3);
            CHECK(sscanf(lb + 1, "%u,%u,%*u,%lf", &qb, &rb, &db) == 3);
            CHECK(qa == qb && ra == rb);
            CHECK_NEAR(da, db, 1e-14);
            rows++;
        }
        CHECK(la && lb && !la[1] && !lb[1]); /* the same number of rows */
        CHECK(rows >= 3);
    }
    remove("cc_g6.off");
    remove("cc_q6.xyz");
    remove("cc_s.csv");
    remove("cc_c.csv");
}

static void test_collapse_cli_refusals(void)
{
    cli_write_file("cc_line.xy", "0 0\n1 0\n1 1\n");
    cli_write_file("cc_p.xy", "0.5 0.5\n");
    CHECK(cli_run(&r, "closest cc_line.xy cc_p.xy --hierarchy collapse") != 0);
    CHECK(strstr(r.err, "triangle mesh") != NULL);
    CHECK(cli_run(&r, "closest cc_line.xy cc_p.xy --hierarchy octree") != 0);
    CHECK_EQ_INT(cli_run(&r, "closest --help"), 0);
    CHECK(strstr(r.out, "--hierarchy") != NULL);
    remove("cc_line.xy");
    remove("cc_p.xy");
}

FL_TEST_MAIN(FL_TEST_CASE(test_collapse_cli_closed_form), FL_TEST_CASE(test_collapse_cli_neighbours),
             FL_TEST_CASE(test_collapse_cli_refusals))

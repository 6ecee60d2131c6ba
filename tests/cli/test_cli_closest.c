/* `flintstone closest` against distances known in closed form. */
#include <math.h>

#include "cli_run.h"
#include "fl_test.h"

static cli_result r;

/* The unit square in the plane z = 0 as two triangles; queries straight above the square are
 * at distance z, queries beyond a corner at the distance to that corner. */
static void test_closest_on_a_square_matches_closed_form(void)
{
    cli_write_file("cl_sq.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
    cli_write_file("cl_q.xyz", "0.25 0.5 2\n0.5 0.5 -0.75\n4 5 0\n1 1 0\n");
    CHECK_EQ_INT(cli_run(&r, "closest cl_sq.off cl_q.xyz --json -o cl_out.csv"), 0);
    CHECK(strstr(r.out, "\"queries\":4") != NULL);
    CHECK(strstr(r.out, "\"max_distance\":5,") != NULL); /* |(4,5,0) - (1,1,0)| = 5 */
    FILE *f = fopen("cl_out.csv", "r");
    char line[512];
    double expect[4] = {2, 0.75, 5, 0};
    int rows = 0;
    if (f && fgets(line, sizeof line, f)) {
        while (fgets(line, sizeof line, f) && rows < 4) {
            double d;
            CHECK(sscanf(line, "%*d,%lf", &d) == 1);
            CHECK_NEAR(d, expect[rows], 1e-15);
            rows++;
        }
    }
    if (f) fclose(f);
    CHECK_EQ_INT(rows, 4);
    remove("cl_out.csv");
    remove("cl_q.xyz");
    remove("cl_sq.off");
}

/* A closed 2D polyline (the unit square's outline): the centre is 0.5 from all four sides, so
 * --within 0.5 lists 4 elements and --k 2 the two nearest. */
static void test_closest_polyline_within_and_k(void)
{
    cli_write_file("cl_ring.xy", "0 0\n1 0\n1 1\n0 1\n");
    cli_write_file("cl_c.xy", "0.5 0.5\n");
    CHECK_EQ_INT(cli_run(&r, "closest cl_ring.xy cl_c.xy --closed --json"), 0);
    CHECK(strstr(r.out, "\"elements\":4") != NULL);
    CHECK(strstr(r.out, "\"max_distance\":0.5,") != NULL);
    CHECK_EQ_INT(cli_run(&r, "closest cl_ring.xy cl_c.xy --closed --within 0.5 -o cl_w.csv"), 0);
    char csv[2048];
    cli_read_file("cl_w.csv", csv, sizeof csv);
    int rows = 0;
    for (const char *p = csv; (p = strchr(p, '\n')) != NULL; p++)
        rows++;
    CHECK_EQ_INT(rows, 1 + 4);
    CHECK_EQ_INT(cli_run(&r, "closest cl_ring.xy cl_c.xy --closed --k 2 -o cl_w.csv"), 0);
    cli_read_file("cl_w.csv", csv, sizeof csv);
    rows = 0;
    for (const char *p = csv; (p = strchr(p, '\n')) != NULL; p++)
        rows++;
    CHECK_EQ_INT(rows, 1 + 2);
    CHECK_EQ_INT(cli_run(&r, "closest cl_ring.xy cl_c.xy --k 2 --within 1"), 1);
    cli_write_file("cl_q3.xyz", "0 0 0\n");
    CHECK_EQ_INT(cli_run(&r, "closest cl_ring.xy cl_q3.xyz"), 2); /* 3D queries, 2D shape */
    remove("cl_w.csv");
    remove("cl_q3.xyz");
    remove("cl_c.xy");
    remove("cl_ring.xy");
}

FL_TEST_MAIN(FL_TEST_CASE(test_closest_on_a_square_matches_closed_form),
             FL_TEST_CASE(test_closest_polyline_within_and_k))

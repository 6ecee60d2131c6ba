/* `flintstone hal`, `inside`, `intersect` on squares whose answers are known by hand. */
#include "cli_run.h"
#include "fl_test.h"

static cli_result r;

static void test_inside_classifies_inside_outside_and_boundary_exactly(void)
{
    cli_write_file("hal_sq.xy", "0 0\n1 0\n1 1\n0 1\n");
    /* inside; outside; on an edge; on a vertex; 0.1 + 0.2 is not 0.3 in binary, but the edge
     * test is exact: (0.3, 0) lies on the bottom edge whatever the rounding of its x. */
    cli_write_file("hal_q.xy", "0.5 0.5\n2 2\n0 0.5\n1 1\n0.3 0\n0.5 -1e-300\n");
    CHECK_EQ_INT(cli_run(&r, "inside hal_sq.xy hal_q.xy --json -o hal_where.csv"), 0);
    CHECK(strstr(r.out, "\"queries\":6") != NULL);
    CHECK(strstr(r.out, "\"inside\":1") != NULL);
    CHECK(strstr(r.out, "\"boundary\":3") != NULL);
    CHECK(strstr(r.out, "\"outside\":2") != NULL);
    char csv[4096];
    cli_read_file("hal_where.csv", csv, sizeof csv);
    CHECK(strstr(csv, "x,y,where\n0.5,0.5,inside\n2,2,outside\n0,0.5,boundary\n1,1,boundary\n") ==
          csv);
    remove("hal_where.csv");
    remove("hal_q.xy");
    remove("hal_sq.xy");
}

static void test_intersect_counts_crossing_edge_pairs(void)
{
    cli_write_file("hal_a.xy", "0 0\n1 0\n1 1\n0 1\n");
    cli_write_file("hal_b.xy", "0.5 0.5\n1.5 0.5\n1.5 1.5\n0.5 1.5\n");
    cli_write_file("hal_c.xy", "3 3\n4 3\n4 4\n3 4\n");
    /* a's top edge crosses b's left edge, a's right edge crosses b's bottom edge. */
    CHECK_EQ_INT(cli_run(&r, "intersect hal_a.xy hal_b.xy --json"), 0);
    CHECK(strstr(r.out, "\"intersect\":true") != NULL);
    CHECK(strstr(r.out, "\"pairs\":2") != NULL);
    CHECK_EQ_INT(cli_run(&r, "intersect hal_a.xy hal_c.xy --json"), 0);
    CHECK(strstr(r.out, "\"intersect\":false") != NULL);
    CHECK(strstr(r.out, "\"pairs\":0") != NULL);
    remove("hal_a.xy");
    remove("hal_b.xy");
    remove("hal_c.xy");
}

static void test_hal_finest_level_is_the_polygon_and_level_zero_is_coarse(void)
{
    cli_write_file("hal_oct.xy", "2 0\n3 1\n3 2\n2 3\n1 3\n0 2\n0 1\n1 0\n");
    CHECK_EQ_INT(cli_run(&r, "hal hal_oct.xy --level 1000 --json"), 0);
    CHECK(strstr(r.out, "\"vertices\":8") != NULL);
    CHECK(strstr(r.out, "\"approx_vertices\":8") != NULL);
    CHECK(strstr(r.out, "\"error\":0") != NULL);
    CHECK_EQ_INT(cli_run(&r, "hal hal_oct.xy --level 0 --json"), 0);
    CHECK(strstr(r.out, "\"approx_vertices\":2") != NULL);
    CHECK_EQ_INT(cli_run(&r, "hal hal_oct.xy"), 1);                       /* neither option */
    CHECK_EQ_INT(cli_run(&r, "hal hal_oct.xy --level 1 --error 0.1"), 1); /* both */
    CHECK_EQ_INT(cli_run(&r, "hal hal_oct.xy --error -1"), 1);
    remove("hal_oct.xy");
}

FL_TEST_MAIN(FL_TEST_CASE(test_inside_classifies_inside_outside_and_boundary_exactly),
             FL_TEST_CASE(test_intersect_counts_crossing_edge_pairs),
             FL_TEST_CASE(test_hal_finest_level_is_the_polygon_and_level_zero_is_coarse))

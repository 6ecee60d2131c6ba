/* `flintstone delaunay`: counts a user can check by hand, the lower-dimensional errors, and
 * output files. */
#include "cli_run.h"
#include "fl_test.h"

static cli_result r;

static void test_delaunay_square_with_centre_and_duplicate(void)
{
    /* 4 corners + centre: 4 triangles, hull of 4 edges; the repeated corner is merged. */
    cli_write_file("dt_sq.xy", "0 0\n1 0\n1 1\n0 1\n0.5 0.5\n1 1\n");
    CHECK_EQ_INT(cli_run(&r, "delaunay dt_sq.xy --verify --json"), 0);
    CHECK(strstr(r.out, "\"dim\":2") != NULL);
    CHECK(strstr(r.out, "\"points\":6") != NULL);
    CHECK(strstr(r.out, "\"unique_points\":5") != NULL);
    CHECK(strstr(r.out, "\"simplices\":4") != NULL);
    CHECK(strstr(r.out, "\"hull_faces\":4") != NULL);
    CHECK(strstr(r.out, "\"valid\":true") != NULL);
    /* The picture holds every point and the 8 edges (4 hull sides, 4 spokes). */
    CHECK_EQ_INT(cli_run(&r, "delaunay dt_sq.xy -o dt_sq.svg"), 0);
    char svg[8192];
    cli_read_file("dt_sq.svg", svg, sizeof svg);
    CHECK(strstr(svg, "</svg>") != NULL);
    remove("dt_sq.svg");
    remove("dt_sq.xy");
}

static void test_delaunay_collinear_points_exit_3_naming_the_situation(void)
{
    cli_write_file("dt_line.xy", "0 0\n1 1\n2 2\n3 3\n");
    CHECK_EQ_INT(cli_run(&r, "delaunay dt_line.xy -o dt_line.off"), 3);
    CHECK(strstr(r.err, "collinear") != NULL);
    FILE *f = fopen("dt_line.off", "r");
    CHECK(f == NULL); /* nothing written on failure */
    if (f) fclose(f);
    remove("dt_line.xy");
}

static void test_delaunay_coplanar_points_exit_3_naming_the_situation(void)
{
    cli_write_file("dt_plane.xyz", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 3 0\n");
    CHECK_EQ_INT(cli_run(&r, "delaunay dt_plane.xyz"), 3);
    CHECK(strstr(r.err, "coplanar") != NULL);
    remove("dt_plane.xyz");
}

static void test_delaunay_cube_corners_and_centre_give_verified_tets(void)
{
    /* 8 cospherical cube corners + centre: the centre is a vertex of every tetrahedron and
     * the 12 hull triangles each cone to it, so there are exactly 12 tetrahedra. */
    cli_write_file("dt_cube.xyz", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
                                  "0.5 0.5 0.5\n");
    CHECK_EQ_INT(cli_run(&r, "delaunay dt_cube.xyz --verify --json -o dt_cube.vtk"), 0);
    CHECK(strstr(r.out, "\"simplices\":12") != NULL);
    CHECK(strstr(r.out, "\"hull_faces\":12") != NULL);
    CHECK(strstr(r.out, "\"valid\":true") != NULL);
    FILE *f = fopen("dt_cube.vtk", "r");
    CHECK(f != NULL);
    if (f) fclose(f);
    remove("dt_cube.xyz");
    remove("dt_cube.vtk");
}

static void test_delaunay_weighted_reports_hidden_ball(void)
{
    /* The ball orthogonal to four balls of weight 20 at the corners of this tetrahedron has
     * centre (2,2,2) and weight 12 - 20 = -8. A ball of weight 0.01 at (1,1,1) has power
     * |(1,1,1) - (2,2,2)|^2 - (-8) - 0.01 = 10.99 > 0 to it: not in conflict, so hidden. */
    cli_write_file("dt_balls.xyzw", "0 0 0 20\n4 0 0 20\n0 4 0 20\n0 0 4 20\n1 1 1 0.01\n");
    CHECK_EQ_INT(cli_run(&r, "delaunay dt_balls.xyzw --weighted --verify --json"), 0);
    CHECK(strstr(r.out, "\"hidden\":1") != NULL);
    CHECK(strstr(r.out, "\"simplices\":1") != NULL);
    CHECK(strstr(r.out, "\"valid\":true") != NULL);
    remove("dt_balls.xyzw");
}

static void test_delaunay_usage_errors(void)
{
    CHECK_EQ_INT(cli_run(&r, "delaunay"), 1);
    CHECK_EQ_INT(cli_run(&r, "delaunay a.xy b.xy"), 1);
    CHECK_EQ_INT(cli_run(&r, "delaunay --bogus a.xy"), 1);
    CHECK_EQ_INT(cli_run(&r, "delaunay --help"), 0);
    CHECK(strstr(r.out, "example:") != NULL);
}

FL_TEST_MAIN(FL_TEST_CASE(test_delaunay_square_with_centre_and_duplicate),
             FL_TEST_CASE(test_delaunay_collinear_points_exit_3_naming_the_situation),
             FL_TEST_CASE(test_delaunay_coplanar_points_exit_3_naming_the_situation),
             FL_TEST_CASE(test_delaunay_cube_corners_and_centre_give_verified_tets),
             FL_TEST_CASE(test_delaunay_weighted_reports_hidden_ball),
             FL_TEST_CASE(test_delaunay_usage_errors))

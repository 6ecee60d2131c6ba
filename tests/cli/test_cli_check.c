/* `flintstone check` on small meshes whose answers are known in closed form. */
#include "cli_run.h"
#include "fl_test.h"

static cli_result r;

static const char *cube_off = "OFF\n8 12 0\n"
                              "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                              "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
                              "3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n";

static void test_check_cube_is_closed_genus_zero_with_unit_volume(void)
{
    cli_write_file("check_cube.off", cube_off);
    CHECK_EQ_INT(cli_run(&r, "check check_cube.off --json"), 0);
    CHECK(strstr(r.out, "\"closed\":true") != NULL);
    CHECK(strstr(r.out, "\"manifold\":true") != NULL);
    CHECK(strstr(r.out, "\"oriented\":true") != NULL);
    CHECK(strstr(r.out, "\"euler\":2") != NULL);
    CHECK(strstr(r.out, "\"genus\":0") != NULL);
    CHECK(strstr(r.out, "\"volume\":1,") != NULL);
    CHECK(strstr(r.out, "\"area\":6,") != NULL);
    CHECK(strstr(r.out, "\"self_intersections\":0") != NULL);
    /* exactly one JSON object, one line */
    CHECK(r.out[0] == '{' && strchr(r.out, '\n') == r.out + strlen(r.out) - 1);
    remove("check_cube.off");
}

static void test_check_open_mesh_has_no_volume_or_genus(void)
{
    cli_write_file("check_open.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
    CHECK_EQ_INT(cli_run(&r, "check check_open.off --json"), 0);
    CHECK(strstr(r.out, "\"closed\":false") != NULL);
    CHECK(strstr(r.out, "\"genus\":null") != NULL);
    CHECK(strstr(r.out, "\"volume\":null") != NULL);
    CHECK(strstr(r.out, "\"boundary_edges\":4") != NULL);
    remove("check_open.off");
}

static void test_check_bundled_torus_has_genus_one(void)
{
    CHECK_EQ_INT(cli_run(&r, "check '" FL_SOURCE_DIR "/data/demo/torus.off' --json"), 0);
    CHECK(strstr(r.out, "\"genus\":1") != NULL);
    CHECK(strstr(r.out, "\"euler\":0") != NULL);
}

static void test_check_bad_input_names_file_and_line_and_exits_2(void)
{
    cli_write_file("check_bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 abc\n3 0 1 2\n");
    CHECK_EQ_INT(cli_run(&r, "check check_bad.off"), 2);
    CHECK(strstr(r.err, "flintstone: error: check_bad.off:5: ") == r.err);
    CHECK(r.out[0] == '\0');
    remove("check_bad.off");
}

static void test_check_missing_file_exits_4(void)
{
    CHECK_EQ_INT(cli_run(&r, "check does-not-exist.off"), 4);
    CHECK(strstr(r.err, "does-not-exist.off") != NULL);
}

static void test_check_polygon_square_with_hole(void)
{
    cli_write_file("check_poly.geojson",
                   "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4],[0,4],[0,0]],"
                   "[[1,1],[1,2],[2,2],[2,1],[1,1]]]}");
    CHECK_EQ_INT(cli_run(&r, "check check_poly.geojson --json"), 0);
    CHECK(strstr(r.out, "\"simple\":true") != NULL);
    CHECK(strstr(r.out, "\"holes\":1") != NULL);
    CHECK(strstr(r.out, "\"area\":15,") != NULL);
    CHECK(strstr(r.out, "\"orientation\":\"ccw\"") != NULL);
    remove("check_poly.geojson");
}

FL_TEST_MAIN(FL_TEST_CASE(test_check_cube_is_closed_genus_zero_with_unit_volume),
             FL_TEST_CASE(test_check_open_mesh_has_no_volume_or_genus),
             FL_TEST_CASE(test_check_bundled_torus_has_genus_one),
             FL_TEST_CASE(test_check_bad_input_names_file_and_line_and_exits_2),
             FL_TEST_CASE(test_check_missing_file_exits_4),
             FL_TEST_CASE(test_check_polygon_square_with_hole))

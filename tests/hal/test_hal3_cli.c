/* `flintstone hal`, `inside`, `intersect` on a unit cube mesh, whose answers are known by hand,
 * and the genus error on the demo torus. */
#include "cli/cli_run.h"
#include "fl_test.h"

static cli_result r;

static const char *cube_off = "OFF\n8 12 0\n"
                              "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                              "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
                              "3 3 7 6\n3 3 6 2\n3 0 4 7\n3 0 7 3\n3 1 2 6\n3 1 6 5\n";

static void test_hal3_cli_levels_and_error_bound(void)
{
    cli_write_file("hal3_cube.off", cube_off);
    CHECK_EQ_INT(cli_run(&r, "hal hal3_cube.off --level 0 --json -o hal3_l0.off"), 0);
    CHECK(strstr(r.out, "\"faces\":12") != NULL);
    CHECK(strstr(r.out, "\"approx_faces\":2") != NULL); /* v_i v_j v_k twice */
    CHECK(strstr(r.out, "\"levels\":") != NULL && strstr(r.out, "\"seconds\":") != NULL);
    char off[4096];
    cli_read_file("hal3_l0.off", off, sizeof off);
    CHECK(strncmp(off, "OFF", 3) == 0);
    /* error 0: every node with a positive error is refined, the cube comes back */
    CHECK_EQ_INT(cli_run(&r, "hal hal3_cube.off --error 0 --json"), 0);
    CHECK(strstr(r.out, "\"approx_faces\":12") != NULL);
    CHECK(strstr(r.out, "\"error\":0") != NULL);
    CHECK_EQ_INT(cli_run(&r, "hal hal3_cube.off --json"), 1); /* neither --level nor --error */
    remove("hal3_l0.off");
    remove("hal3_cube.off");
}

static void test_hal3_cli_inside_and_intersect(void)
{
    cli_write_file("hal3_cube.off", cube_off);
    /* inside; outside; on a face; on a vertex; on an edge; outside next to a face */
    cli_write_file("hal3_q.xyz", "0.5 0.5 0.5\n2 2 2\n1 0.5 0.5\n0 0 0\n0.5 0 0\n1.5 0.5 0.5\n");
    CHECK_EQ_INT(cli_run(&r, "inside hal3_cube.off hal3_q.xyz --json -o hal3_where.csv"), 0);
    CHECK(strstr(r.out, "\"queries\":6") != NULL);
    CHECK(strstr(r.out, "\"inside\":1") != NULL);
    CHECK(strstr(r.out, "\"boundary\":3") != NULL);
    CHECK(strstr(r.out, "\"outside\":2") != NULL);
    char csv[4096];
    cli_read_file("hal3_where.csv", csv, sizeof csv);
    CHECK(strstr(csv, "x,y,z,where\n0.5,0.5,0.5,inside\n2,2,2,outside\n1,0.5,0.5,boundary\n") ==
          csv);
    /* a copy moved by 1 in x touches along the face x = 1; moved by 3, it is apart */
    cli_write_file("hal3_far.off", "OFF\n8 12 0\n"
                                   "3 0 0\n4 0 0\n4 1 0\n3 1 0\n3 0 1\n4 0 1\n4 1 1\n3 1 1\n"
                                   "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
                                   "3 3 7 6\n3 3 6 2\n3 0 4 7\n3 0 7 3\n3 1 2 6\n3 1 6 5\n");
    cli_write_file("hal3_touch.off", "OFF\n8 12 0\n"
                                     "1 0 0\n2 0 0\n2 1 0\n1 1 0\n1 0 1\n2 0 1\n2 1 1\n1 1 1\n"
                                     "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
                                     "3 3 7 6\n3 3 6 2\n3 0 4 7\n3 0 7 3\n3 1 2 6\n3 1 6 5\n");
    CHECK_EQ_INT(cli_run(&r, "intersect hal3_cube.off hal3_touch.off --json"), 0);
    CHECK(strstr(r.out, "\"intersect\":true") != NULL);
    CHECK_EQ_INT(cli_run(&r, "intersect hal3_cube.off hal3_far.off --json"), 0);
    CHECK(strstr(r.out, "\"intersect\":false") != NULL);
    CHECK(strstr(r.out, "\"pairs\":0") != NULL);
    remove("hal3_where.csv");
    remove("hal3_q.xyz");
    remove("hal3_far.off");
    remove("hal3_touch.off");
    remove("hal3_cube.off");
}

static void test_hal3_cli_names_the_genus_of_a_torus(void)
{
    CHECK_EQ_INT(cli_run(&r, "hal " FL_SOURCE_DIR "/data/demo/torus.off --level 1"), 2);
    CHECK(strstr(r.err, "genus 1: the HAL tree needs a sphere-like surface") != NULL);
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_hal3_cli_levels_and_error_bound),
        FL_TEST_CASE(test_hal3_cli_inside_and_intersect),
        FL_TEST_CASE(test_hal3_cli_names_the_genus_of_a_torus),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}

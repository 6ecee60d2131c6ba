/* `flintstone skin --balls`: the CLI contract (exit codes, --json keys, -o mesh) on ball sets
 * whose skin topology is known: two separate balls give two spheres (Euler characteristic 4). */
#include "cli/cli_run.h"
#include "fl_test.h"

static void test_cli_skin_two_balls_writes_closed_mesh_with_two_spheres(void)
{
    cli_write_file("skin_two.xyzw", "# x y z w\n0 0 0 1\n3 0 0 0.81\n");
    cli_result r;
    CHECK_EQ_INT(cli_run(&r, "skin --balls skin_two.xyzw --t 0.4 -o skin_two.off --json"), 0);
    CHECK_MSG(strstr(r.out, "\"balls\":2") != NULL, "%s", r.out);
    CHECK_MSG(strstr(r.out, "\"euler\":4") != NULL, "%s", r.out);
    CHECK_MSG(strstr(r.out, "\"seconds\":") != NULL, "%s", r.out);
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(fl_read_mesh("skin_two.off", &m, &err), FL_OK, &err);
    fl_mesh_report rep;
    CHECK_STATUS(fl_mesh_check(&m, NULL, &rep, &err), FL_OK, &err);
    CHECK(rep.closed && rep.manifold && rep.oriented);
    CHECK_EQ_INT(rep.components, 2);
    CHECK_EQ_INT(rep.self_intersections, 0);
    fl_mesh_report_free(&rep);
    fl_mesh_free(&m);
    remove("skin_two.off");
    remove("skin_two.xyzw");
}

static void test_cli_skin_reports_usage_and_input_errors(void)
{
    cli_result r;
    CHECK_EQ_INT(cli_run(&r, "skin --help"), 0);
    CHECK(strstr(r.out, "example:") != NULL);
    CHECK_EQ_INT(cli_run(&r, "skin"), 1);
    cli_write_file("skin_one.xyzw", "0 0 0 1\n");
    CHECK_EQ_INT(cli_run(&r, "skin --balls skin_one.xyzw --t 1.5"), 1);
    CHECK_EQ_INT(cli_run(&r, "skin --balls skin_missing_file.xyzw"), 4);
    cli_write_file("skin_neg.xyzw", "0 0 0 -1\n");
    CHECK_EQ_INT(cli_run(&r, "skin --balls skin_neg.xyzw"), 2);
    CHECK(strstr(r.err, "positive radius") != NULL);
    remove("skin_one.xyzw");
    remove("skin_neg.xyzw");
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_cli_skin_two_balls_writes_closed_mesh_with_two_spheres),
        FL_TEST_CASE(test_cli_skin_reports_usage_and_input_errors),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}

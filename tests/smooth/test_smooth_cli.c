/* The `flintstone smooth` command: JSON summary fields, outputs that read back, clear errors. */
#include "cli/cli_run.h"
#include "fl_test.h"

static double json_number(const char *json, const char *key)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\":", key);
    const char *p = strstr(json, pat);
    return p ? strtod(p + strlen(pat), NULL) : NAN;
}

static void test_smooth_cli_mesh_json_and_watertight_output(void)
{
    cli_result r;
    cli_write_file("smooth_cli_octa.off",
                   "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                   "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n"
                   "3 3 1 5\n3 0 3 5\n");
    CHECK_EQ_INT(cli_run(&r, "smooth smooth_cli_octa.off --tess 5 -o smooth_cli_out.off --json"),
                 0);
    /* auto: 3 patches a triangle where the three-split is kept, 6 where the six-split is */
    double six = json_number(r.out, "six_split_triangles"), patches = 3 * (8 - six) + 6 * six;
    CHECK(six >= 0 && six <= 8);
    CHECK_EQ_INT(json_number(r.out, "patches"), patches);
    CHECK(json_number(r.out, "max_vertex_error") <= 1e-12);
    CHECK(json_number(r.out, "max_normal_error") <= 1e-12);
    CHECK(json_number(r.out, "max_edge_normal_jump_deg") < 1e-7);
    CHECK(json_number(r.out, "orientation_repairs") == 0);
    CHECK(json_number(r.out, "max_deviation") > 0);
    CHECK(json_number(r.out, "seconds") >= 0);
    fl_mesh m;
    fl_mesh_report rep;
    fl_error err;
    CHECK_STATUS(fl_read_mesh("smooth_cli_out.off", &m, &err), FL_OK, &err);
    CHECK_STATUS(fl_mesh_check(&m, NULL, &rep, &err), FL_OK, &err);
    CHECK(rep.closed && rep.manifold && rep.oriented && rep.self_intersections == 0);
    CHECK_EQ_INT(m.triangle_count, patches * 25);
    fl_mesh_report_free(&rep);
    fl_mesh_free(&m);
    CHECK_EQ_INT(cli_run(&r, "smooth smooth_cli_octa.off --scheme pn --json"), 0);
    CHECK(json_number(r.out, "max_edge_normal_jump_deg") > 1);
    CHECK_EQ_INT(cli_run(&r, "smooth smooth_cli_octa.off -o smooth_cli_out.bez --quiet"), 0);
    fl_g1_surface s;
    CHECK_STATUS(fl_g1_read_bez("smooth_cli_out.bez", &s, &err), FL_OK, &err);
    CHECK_EQ_INT(s.patch_count, patches);
    fl_g1_surface_free(&s);
    remove("smooth_cli_out.off");
    remove("smooth_cli_out.bez");
    remove("smooth_cli_octa.off");
}

static void test_smooth_cli_polygon_outputs(void)
{
    cli_result r;
    cli_write_file("smooth_cli_sq.xy", "0 0\n2 0\n2 1\n0 1\n");
    CHECK_EQ_INT(cli_run(&r, "smooth smooth_cli_sq.xy --tangents uniform --samples 5 "
                             "-o smooth_cli_sq_out.xy --json"),
                 0);
    CHECK_EQ_INT(json_number(r.out, "segments"), 4);
    CHECK(json_number(r.out, "max_tangent_jump_deg") < 1e-9);
    fl_polygon p;
    fl_error err;
    CHECK_STATUS(fl_read_polygon("smooth_cli_sq_out.xy", &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.vertex_count, 20);
    fl_polygon_free(&p);
    CHECK_EQ_INT(cli_run(&r, "smooth smooth_cli_sq.xy -o smooth_cli_sq.svg --quiet"), 0);
    remove("smooth_cli_sq.svg");
    remove("smooth_cli_sq_out.xy");
    remove("smooth_cli_sq.xy");
}

static void test_smooth_cli_errors(void)
{
    cli_result r;
    cli_write_file("smooth_cli_open.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    CHECK_EQ_INT(cli_run(&r, "smooth smooth_cli_open.off"), 2);
    CHECK(strstr(r.err, "not closed") != NULL);
    CHECK_EQ_INT(cli_run(&r, "smooth smooth_cli_open.off --scheme six-split"), 2);
    CHECK_EQ_INT(cli_run(&r, "smooth smooth_cli_open.off --scheme seven-split"), 1);
    CHECK_EQ_INT(cli_run(&r, "smooth smooth_cli_open.off --tension 2"), 1);
    CHECK_EQ_INT(cli_run(&r, "smooth"), 1);
    CHECK_EQ_INT(cli_run(&r, "smooth --help"), 0);
    CHECK(strstr(r.out, "example:") != NULL);
    remove("smooth_cli_open.off");
}

FL_TEST_MAIN(FL_TEST_CASE(test_smooth_cli_mesh_json_and_watertight_output),
             FL_TEST_CASE(test_smooth_cli_polygon_outputs), FL_TEST_CASE(test_smooth_cli_errors))

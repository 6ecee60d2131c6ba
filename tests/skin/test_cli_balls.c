/* `flintstone balls MESH --epsilon E` and `flintstone skin MESH --epsilon E` on the unit cube:
 * the CLI contract (exit codes, --json keys, -o files) and the guarantees checked here
 * independently of the library: every written ball has a positive radius and its centre in the
 * closed cube, the ball file has as many lines as the JSON says, and the written skin mesh is a
 * closed 2-manifold sphere (Euler characteristic 2) whose vertices all lie within epsilon of
 * the cube's surface (distance to a box computed directly), as the certified Hausdorff bound
 * the command reports (<= epsilon) implies. Open meshes and bad epsilons are input errors. */
#include <math.h>

#include "cli/cli_run.h"
#include "fl_test.h"

static const char *cube_off = "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n"
                              "0 1 1\n3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
                              "3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n";

/* The number after "key": in a one-line JSON object, NaN when absent. */
static double json_number(const char *json, const char *key)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\":", key);
    const char *p = strstr(json, pat);
    return p ? strtod(p + strlen(pat), NULL) : NAN;
}

/* Distance from p to the surface of the unit cube [0, 1]^3. */
static double cube_surface_distance(const double *p)
{
    double out2 = 0, in = HUGE_VAL;
    for (int c = 0; c < 3; c++) {
        double d = p[c] < 0 ? -p[c] : p[c] > 1 ? p[c] - 1 : 0;
        out2 += d * d;
        in = fmin(in, fmin(fabs(p[c]), fabs(1 - p[c])));
    }
    return out2 > 0 ? sqrt(out2) : in;
}

static void test_cli_balls_cube_writes_xyzr_balls_inside(void)
{
    cli_write_file("cli_balls_cube.off", cube_off);
    cli_result r;
    CHECK_EQ_INT(cli_run(&r, "balls cli_balls_cube.off --epsilon 0.5 -o cli_balls.txt --json"),
                 0);
    double balls = json_number(r.out, "balls"), eps = json_number(r.out, "epsilon");
    double h = json_number(r.out, "hausdorff_upper");
    CHECK_MSG(balls > 0 && json_number(r.out, "boundary_balls") > 0, "%s", r.out);
    CHECK_MSG(eps == 0.5 && h > 0 && h <= eps, "%s", r.out);
    /* hausdorff_* certify the union of B_perp itself, skin_hausdorff_upper the skin of B* */
    double hl = json_number(r.out, "hausdorff_lower"), hs = json_number(r.out, "skin_hausdorff_upper");
    CHECK_MSG(hl > 0 && hl <= h && h - hl <= eps / 50 * 1.001 && hs > 0 && hs <= eps, "%s", r.out);
    CHECK_MSG(json_number(r.out, "euler") == 2 && json_number(r.out, "seconds") >= 0, "%s",
              r.out);
    FILE *f = fopen("cli_balls.txt", "r");
    CHECK(f != NULL);
    size_t lines = 0, bad = 0;
    double b[4];
    while (f && fscanf(f, "%lf %lf %lf %lf", &b[0], &b[1], &b[2], &b[3]) == 4) {
        lines++;
        int inside = b[0] >= 0 && b[0] <= 1 && b[1] >= 0 && b[1] <= 1 && b[2] >= 0 && b[2] <= 1;
        bad += !inside || !(b[3] > 0 && b[3] <= 1);
    }
    if (f) fclose(f);
    CHECK_MSG((double)lines == balls, "%zu lines, %g balls", lines, balls);
    CHECK_MSG(bad == 0, "%zu balls with a centre outside the cube or a bad radius", bad);
    remove("cli_balls.txt");
    remove("cli_balls_cube.off");
}

static void test_cli_skin_mesh_epsilon_writes_verified_sphere(void)
{
    cli_write_file("cli_skin_cube.off", cube_off);
    cli_result r;
    CHECK_EQ_INT(cli_run(&r, "skin cli_skin_cube.off --epsilon 0.5 -o cli_skin.off --star "
                             "cli_star.xyzw --json"),
                 0);
    double eps = 0.5, h = json_number(r.out, "hausdorff_upper");
    /* --star: B*, one "x y z w" line a ball, with negative weights (the alpha simplices' balls) */
    FILE *f = fopen("cli_star.xyzw", "r");
    CHECK(f != NULL);
    size_t lines = 0, negative = 0;
    double b[4];
    while (f && fscanf(f, "%lf %lf %lf %lf", b, b + 1, b + 2, b + 3) == 4) {
        lines++;
        negative += b[3] < 0;
    }
    if (f) fclose(f);
    CHECK_MSG((double)lines == json_number(r.out, "balls") && negative > 0 && negative < lines,
              "%zu lines, %zu negative, %s", lines, negative, r.out);
    remove("cli_star.xyzw");
    CHECK_MSG(json_number(r.out, "euler") == 2 && json_number(r.out, "euler_input") == 2, "%s",
              r.out);
    CHECK_MSG(h > 0 && h <= eps && json_number(r.out, "balls") > 0, "%s", r.out);
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(fl_read_mesh("cli_skin.off", &m, &err), FL_OK, &err);
    CHECK((double)m.triangle_count == json_number(r.out, "faces"));
    fl_mesh_report rep;
    fl_mesh_check_options co = {0};
    co.skip_self_intersections = 1;
    CHECK_STATUS(fl_mesh_check(&m, &co, &rep, &err), FL_OK, &err);
    CHECK(rep.closed && rep.manifold && rep.oriented && rep.euler == 2);
    fl_mesh_report_free(&rep);
    double worst = 0;
    for (size_t i = 0; i < m.vertex_count; i++)
        worst = fmax(worst, cube_surface_distance(m.xyz + 3 * i));
    CHECK_MSG(worst <= h + 1e-9, "a skin vertex lies %g from the cube, above the bound %g", worst,
              h);
    fl_mesh_free(&m);
    remove("cli_skin.off");
    remove("cli_skin_cube.off");
}

static void test_cli_balls_rejects_open_mesh_and_bad_epsilon(void)
{
    /* the cube without its last face: open */
    cli_write_file("cli_balls_open.off", "OFF\n8 11 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n"
                                         "1 1 1\n0 1 1\n3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n"
                                         "3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n"
                                         "3 2 7 6\n3 3 0 4\n");
    cli_write_file("cli_balls_ok.off", cube_off);
    cli_result r;
    CHECK_EQ_INT(cli_run(&r, "balls cli_balls_open.off --epsilon 0.5"), 2);
    CHECK_MSG(strstr(r.err, "closed") != NULL, "%s", r.err);
    CHECK_EQ_INT(cli_run(&r, "skin cli_balls_open.off --epsilon 0.5"), 2);
    CHECK_EQ_INT(cli_run(&r, "balls cli_balls_ok.off --epsilon 0"), 2);
    CHECK_EQ_INT(cli_run(&r, "balls cli_balls_ok.off --epsilon nan"), 2);
    CHECK_EQ_INT(cli_run(&r, "skin cli_balls_ok.off --epsilon -1"), 2);
    CHECK_EQ_INT(cli_run(&r, "balls cli_balls_ok.off --epsilon 0.5 --placement voronoi"), 1);
    CHECK_MSG(strstr(r.err, "alg1 or subdivision") != NULL, "%s", r.err);
    CHECK_EQ_INT(cli_run(&r, "skin cli_balls_ok.off --epsilon 0.5 --placement"), 1);
    CHECK_EQ_INT(cli_run(&r, "balls cli_balls_ok.off"), 1);
    CHECK_EQ_INT(cli_run(&r, "skin cli_balls_ok.off"), 1);
    CHECK_EQ_INT(cli_run(&r, "balls --help"), 0);
    CHECK(strstr(r.out, "example:") != NULL);
    remove("cli_balls_open.off");
    remove("cli_balls_ok.off");
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_cli_balls_rejects_open_mesh_and_bad_epsilon),
        FL_TEST_CASE(test_cli_balls_cube_writes_xyzr_balls_inside),
        FL_TEST_CASE(test_cli_skin_mesh_epsilon_writes_verified_sphere),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}

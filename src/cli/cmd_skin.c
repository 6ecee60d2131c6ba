/* flintstone skin --balls BALLS [--t T] [--cell H] [-o SKIN.off] [--json]
 * flintstone skin MESH --epsilon E [--t T] [--cell H] [-o SKIN.off] [--json]
 * A closed triangle mesh of the skin surface skin^t(B) of a ball set (Cheng & Tan §6.1), or of
 * the verified epsilon-approximation skin^t(B*) of a polyhedron (§4-6, fl_skin_approx_build). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

static const char *usage_text =
    "usage: flintstone skin --balls BALLS [--t T] [--cell H] [--grade G] [--repair N]\n"
    "       [-o SKIN.off] [--json] [--quiet]\n"
    "       flintstone skin MESH --epsilon E [--t T] [--cell H] [--grade G] [--repair N]\n"
    "       [--placement P] [--star B] [-o SKIN.off] [--json]\n"
    "\n"
    "Triangulates the skin surface skin^t(B) of a ball set: the boundary of the union of the\n"
    "convex combinations of the balls, each shrunk to sqrt(t) times its radius. BALLS holds one\n"
    "ball a line, \"x y z w\" with w the squared radius (.xyzw .txt .csv). The mesh is closed,\n"
    "oriented and 2-manifold; its vertices lie on the skin to rounding. Its topology is\n"
    "checked: the skin's Euler characteristic is exactly twice the union of balls' (computed\n"
    "exactly). By default the mesh is made on the graded grid of grade 1.5, refined locally\n"
    "round false handles and bubbles (--repair); when its Euler characteristic or number of\n"
    "components is still wrong it is made again at grade 0.75, then on the uniform grid of the\n"
    "default cell; the first mesh that passes is kept. If none passes (or --cell / --grade\n"
    "was given and the check fails) the mesh is written with a warning on stderr.\n"
    "\n"
    "With MESH (a closed, oriented, 2-manifold triangle mesh without self-intersections) and\n"
    "--epsilon, the balls are B* of Cheng & Tan's approximation of the object within E (see\n"
    "flintstone balls) and the skin is verified: its certified Hausdorff distance to MESH is\n"
    "<= E and its Euler characteristic is MESH's, else the command fails.\n"
    "\n"
    "  --balls B    the ball set\n"
    "  --epsilon E  with MESH: the Hausdorff tolerance (> 0)\n"
    "  --t T        shrink factor in (0, 1), default 0.5\n"
    "  --placement P  with MESH: alg1 (default, §4.2 Algorithm 1) or subdivision (see balls)\n"
    "  --star B     with MESH: also write B* (\"x y z w\" lines, w the weight, negative for\n"
    "               the orthogonal balls of alpha simplices), readable by --balls\n"
    "  --cell H     uniform grid of spacing H, one mesh (--balls default: the checked grids\n"
    "               above, whose uniform cell is sqrt(t) times the smallest radius / 4,\n"
    "               smaller for thin necks; with MESH: 0.4 E); features thinner than H can be\n"
    "               missed\n"
    "  --grade G    graded grid: octree cells of G times the local feature size of the skin\n"
    "               (shrunk radius, neck waist), at most H; exactly triangulated, crack-free;\n"
    "               one mesh. With MESH: default uniform, then graded 2.2 when the topology\n"
    "               is wrong\n"
    "  --repair N   graded grid: while the mesh has more genus or components than the skin\n"
    "               (the union of balls' Betti numbers), refine the grid along the mesh round\n"
    "               its small handles and bubbles and mesh again, at most N times (default:\n"
    "               3 in the checked default, 0 with --grade and with MESH)\n"
    "  -o FILE      the mesh (.off .obj .ply .stl)\n"
    "  --json       --balls: balls, vertices, faces, euler, genus, closed, manifold, cell,\n"
    "               max_vertex_offset, euler_expected, components, components_expected,\n"
    "               topology_ok, grade (0: uniform),\n"
    "               attempts, repairs, seconds; MESH: balls (|B*|), faces, euler,\n"
    "               euler_input, epsilon, hausdorff_upper, rounds, cell, grade, repairs,\n"
    "               seconds\n"
    "\n"
    "example: flintstone skin --balls balls.xyzw --t 0.5 -o skin.off --json\n"
    "example: flintstone skin cube.off --epsilon 0.5 -o skin.off --json\n";

typedef struct skin_args {
    const char *balls, *mesh, *star;
    double t, cell, epsilon, grade;
    int has_epsilon, repair;
    fl_skin_placement placement;
} skin_args;

static int parse(int argc, char **argv, cli_common *c, skin_args *a)
{
    for (int i = 1; i < argc; i++) {
        int r = cli_common_option(c, argc, argv, &i);
        if (r < 0) return 1;
        if (r > 0) continue;
        const char *o = argv[i];
        int value = !strcmp(o, "--balls") || !strcmp(o, "--t") || !strcmp(o, "--cell") ||
                    !strcmp(o, "--epsilon") || !strcmp(o, "--placement") || !strcmp(o, "--star") ||
                    !strcmp(o, "--grade") || !strcmp(o, "--repair");
        if (value && i + 1 >= argc) return cli_fail(1, "skin: %s needs a value", o);
        if (!strcmp(o, "--balls")) {
            a->balls = argv[++i];
        } else if (!strcmp(o, "--t")) {
            if (cli_parse_double(argv[++i], &a->t) || !(a->t > 0 && a->t < 1))
                return cli_fail(1, "skin: --t takes a number in (0, 1)");
        } else if (!strcmp(o, "--cell")) {
            if (cli_parse_double(argv[++i], &a->cell) || !(a->cell > 0) || !isfinite(a->cell))
                return cli_fail(1, "skin: --cell takes a number > 0");
        } else if (!strcmp(o, "--grade")) {
            if (cli_parse_double(argv[++i], &a->grade) || !(a->grade > 0) || !isfinite(a->grade))
                return cli_fail(1, "skin: --grade takes a number > 0");
        } else if (!strcmp(o, "--repair")) {
            double rounds;
            if (cli_parse_double(argv[++i], &rounds) || !(rounds >= 0 && rounds <= 100) ||
                rounds != floor(rounds))
                return cli_fail(1, "skin: --repair takes a whole number in [0, 100]");
            a->repair = (int)rounds;
        } else if (!strcmp(o, "--epsilon")) {
            /* a bad value is bad input to the approximation (FL_ERR_INPUT), as in the library */
            if (cli_parse_double(argv[++i], &a->epsilon) || !(a->epsilon > 0) ||
                !isfinite(a->epsilon))
                return cli_fail(2, "skin: --epsilon takes a finite number > 0");
            a->has_epsilon = 1;
        } else if (!strcmp(o, "--star")) {
            a->star = argv[++i];
        } else if (!strcmp(o, "--placement")) {
            if (cli_parse_skin_placement(argv[++i], &a->placement))
                return cli_fail(1, "skin: --placement takes alg1 or subdivision");
        } else if (o[0] == '-' && o[1]) {
            return cli_fail(1, "skin: unknown option '%s' (see --help)", o);
        } else if (!a->mesh) {
            a->mesh = o;
        } else {
            return cli_fail(1, "skin: unexpected argument '%s'", o);
        }
    }
    return 0;
}

static void print_summary(const cli_common *c, const fl_balls *b, const fl_mesh *m,
                          const fl_mesh_report *rep, const fl_skin_stats *st,
                          const fl_skin_check *chk, double seconds)
{
    if (c->json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_uint(&j, "balls", b->count);
        cli_json_uint(&j, "vertices", m->vertex_count);
        cli_json_uint(&j, "faces", m->triangle_count);
        cli_json_int(&j, "euler", rep->euler);
        cli_json_int(&j, "genus", rep->genus);
        cli_json_bool(&j, "closed", rep->closed);
        cli_json_bool(&j, "manifold", rep->manifold);
        cli_json_double(&j, "cell", st->cell);
        cli_json_double(&j, "max_vertex_offset", st->max_vertex_offset);
        cli_json_int(&j, "euler_expected", chk->euler_expected);
        cli_json_int(&j, "components", chk->components);
        cli_json_int(&j, "components_expected", chk->components_expected);
        cli_json_bool(&j, "topology_ok", chk->topology_ok);
        cli_json_double(&j, "grade", chk->grade);
        cli_json_int(&j, "attempts", chk->attempts);
        cli_json_int(&j, "repairs", st->repairs);
        cli_json_double(&j, "seconds", seconds);
        cli_json_end(&j);
    } else if (!c->quiet) {
        char grid[64];
        if (chk->grade > 0)
            snprintf(grid, sizeof grid, "grade %g, smallest cell %g", chk->grade, st->cell);
        else
            snprintf(grid, sizeof grid, "cell %g", st->cell);
        printf("skin of %zu balls: %zu vertices, %zu faces, Euler characteristic %lld%s "
               "(expected %lld; %s, %d mesh%s, %.3f s)\n",
               b->count, m->vertex_count, m->triangle_count, rep->euler,
               rep->closed && rep->manifold ? ", closed 2-manifold" : "", chk->euler_expected, grid,
               chk->attempts, chk->attempts == 1 ? "" : "es", seconds);
    }
    if (!chk->topology_ok)
        fprintf(stderr,
                "flintstone skin: warning: the mesh has Euler characteristic %lld in %lld "
                "component%s where the union of balls gives %lld in %lld; the grid does not "
                "resolve the skin's topology (%s); try a smaller --cell or --grade\n",
                rep->euler, chk->components, chk->components == 1 ? "" : "s", chk->euler_expected,
                chk->components_expected, chk->grade > 0 ? "graded grid" : "uniform grid");
}

/* B* as "x y z w" lines (the --balls format), written atomically. */
static fl_status write_xyzw(const char *path, const fl_balls *b, fl_error *err)
{
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st) return st;
    for (size_t i = 0; i < b->count; i++) {
        const double *p = b->xyzw + 4 * i;
        fprintf(out.fp, "%.17g %.17g %.17g %.17g\n", p[0], p[1], p[2], p[3]);
    }
    return fl_out_commit(&out, err);
}

/* skin MESH --epsilon E: the verified skin^t(B*) of the approximation of MESH. */
static int skin_of_mesh(const cli_common *c, const skin_args *a)
{
    fl_error err;
    fl_mesh mesh = {0};
    fl_skin_approx ap;
    memset(&ap, 0, sizeof ap);
    cli_progress prog;
    cli_progress_init(&prog, c);
    double t0 = cli_now();
    fl_status st = fl_read_mesh(a->mesh, &mesh, &err);
    if (st == FL_OK) {
        fl_skin_approx_options opt = {0};
        opt.t = a->t;
        opt.cell = a->cell;
        opt.grade = a->grade;
        opt.repair = a->repair;
        opt.placement = a->placement;
        opt.progress = cli_progress_fn;
        opt.progress_user = &prog;
        st = fl_skin_approx_build(&mesh, a->epsilon, &opt, &ap, &err);
        cli_progress_done(&prog);
    }
    double seconds = cli_now() - t0;
    if (st == FL_OK && !ap.verified)
        st = fl_fail(&err, FL_ERR_ALGORITHM, NULL, -1,
                     "skin: not verified after %d rounds (Hausdorff <= %g, Euler %lld vs %lld "
                     "of the input); try a smaller epsilon than %g",
                     ap.rounds, ap.hausdorff[1], ap.euler, ap.euler_input, a->epsilon);
    if (st == FL_OK && c->output) st = fl_write_mesh(c->output, &ap.skin, &err);
    if (st == FL_OK && a->star) st = write_xyzw(a->star, &ap.star, &err);
    if (st == FL_OK && c->json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_uint(&j, "balls", ap.star.count);
        cli_json_uint(&j, "faces", ap.skin.triangle_count);
        cli_json_int(&j, "euler", ap.euler);
        cli_json_int(&j, "euler_input", ap.euler_input);
        cli_json_double(&j, "epsilon", a->epsilon);
        cli_json_double(&j, "hausdorff_upper", ap.hausdorff[1]);
        cli_json_int(&j, "rounds", ap.rounds);
        cli_json_double(&j, "cell", ap.cell);
        cli_json_double(&j, "grade", ap.grade);
        cli_json_int(&j, "repairs", ap.repairs);
        cli_json_double(&j, "seconds", seconds);
        cli_json_end(&j);
    } else if (st == FL_OK && !c->quiet) {
        printf("skin of %zu balls approximating %s: %zu faces, Euler characteristic %lld (input "
               "%lld), certified Hausdorff <= %g <= epsilon %g (%.3f s)\n",
               ap.star.count, a->mesh, ap.skin.triangle_count, ap.euler, ap.euler_input,
               ap.hausdorff[1], a->epsilon, seconds);
    }
    fl_skin_approx_free(&ap);
    fl_mesh_free(&mesh);
    return st == FL_OK ? 0 : cli_report(&err);
}

int cmd_skin(int argc, char **argv)
{
    cli_common c = {0};
    skin_args a = {0};
    int bad = parse(argc, argv, &c, &a);
    if (bad) return bad;
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    if (a.mesh && a.balls) return cli_fail(1, "skin: give either --balls BALLS or MESH, not both");
    if (a.mesh && !a.has_epsilon) return cli_fail(1, "skin: MESH needs --epsilon E (see --help)");
    if (a.has_epsilon && !a.mesh) return cli_fail(1, "skin: --epsilon needs a MESH (see --help)");
    int code = cli_check_output(c.output, "off obj ply stl");
    if (code) return code;
    if (a.mesh) return skin_of_mesh(&c, &a);
    if (!a.balls) return cli_fail(1, "skin: needs --balls BALLS or MESH --epsilon E (see --help)");
    fl_error err;
    fl_balls balls = {0};
    fl_mesh mesh = {0};
    fl_mesh_report rep = {0};
    fl_skin_stats stats;
    fl_skin_check check = {0};
    cli_progress prog;
    cli_progress_init(&prog, &c);
    double t0 = cli_now();
    fl_status st = fl_read_balls(a.balls, &balls, &err);
    if (st == FL_OK) {
        fl_skin_options opt = {0};
        opt.t = a.t;
        opt.cell = a.cell;
        opt.grade = a.grade;
        opt.repair = a.repair;
        opt.progress = cli_progress_fn;
        opt.progress_user = &prog;
        st = fl_skin_mesh_checked(balls.xyzw, balls.count, &opt, &mesh, &stats, &check, &err);
        cli_progress_done(&prog);
    }
    double seconds = cli_now() - t0;
    fl_mesh_check_options copt = {0};
    copt.skip_self_intersections = 1;
    if (st == FL_OK) st = fl_mesh_check(&mesh, &copt, &rep, &err);
    if (st == FL_OK && c.output) st = fl_write_mesh(c.output, &mesh, &err);
    if (st == FL_OK) print_summary(&c, &balls, &mesh, &rep, &stats, &check, seconds);
    fl_mesh_report_free(&rep);
    fl_mesh_free(&mesh);
    fl_balls_free(&balls);
    return st == FL_OK ? 0 : cli_report(&err);
}

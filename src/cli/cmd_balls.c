/* flintstone balls MESH --epsilon E [--t T] [-o BALLS.txt] [--json]
 * A union of balls B_perp approximating a closed polyhedron within epsilon (Cheng & Tan §4-5),
 * verified through the skin of B* (fl_skin_approx_build) and through the certified Hausdorff
 * distance of the union's own boundary (fl_skin_union_hausdorff; docs/skin.md). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

static const char *usage_text =
    "usage: flintstone balls MESH --epsilon E [--t T] [--placement P] [-o BALLS.txt] [--json]\n"
    "       [--quiet]\n"
    "\n"
    "Approximates the object bounded by MESH (a closed, oriented, 2-manifold triangle mesh\n"
    "without self-intersections: .off .obj .ply .stl) by a union of balls B_perp (Cheng & Tan\n"
    "§4-5): protecting balls B of radius <= 0.8 E on the surface (placed by Algorithm 1 of §4.2\n"
    "at the positive vertices of restricted power diagrams), then the orthogonal balls of\n"
    "the Voronoi vertices of B inside the object. The result is verified, not only constructed:\n"
    "the skin surface of B* (B_perp and the negative orthogonal balls of §6.2) is meshed and its\n"
    "certified Hausdorff distance to MESH must be <= E with the same Euler characteristic;\n"
    "otherwise the construction repeats (3 rounds: a finer skin grid after a wrong Euler\n"
    "characteristic, smaller balls after a Hausdorff miss), then it fails. Then the\n"
    "Hausdorff distance between the boundary of the union of B_perp itself and MESH is\n"
    "certified (to E/50) and must be <= E too (exit 3 otherwise).\n"
    "\n"
    "  --epsilon E  the Hausdorff tolerance (> 0, in the mesh's units)\n"
    "  --t T        shrink factor of the verifying skin in (0, 1), default 0.5\n"
    "  --placement P  how B is placed: alg1 (default, §4.2 Algorithm 1) or subdivision\n"
    "               (bisect edges, 4-split triangles until covered)\n"
    "  -o FILE      B_perp, one \"x y z r\" line a ball (r the radius)\n"
    "  --json       balls (|B_perp|), boundary_balls (|B|, on the surface), epsilon,\n"
    "               hausdorff_lower / hausdorff_upper (certified, the boundary of the union\n"
    "               of B_perp to MESH), skin_hausdorff_upper (certified, skin of B* to MESH),\n"
    "               euler, euler_input (of the skin mesh and MESH), rounds,\n"
    "               union_seconds (the union's bound), seconds (all)\n"
    "\n"
    "example: flintstone balls cube.off --epsilon 0.5 -o balls.txt --json\n";

typedef struct balls_args {
    const char *mesh;
    double epsilon, t;
    int has_epsilon;
    fl_skin_placement placement;
} balls_args;

static int parse(int argc, char **argv, cli_common *c, balls_args *a)
{
    for (int i = 1; i < argc; i++) {
        int r = cli_common_option(c, argc, argv, &i);
        if (r < 0) return 1;
        if (r > 0) continue;
        const char *o = argv[i];
        int value = !strcmp(o, "--epsilon") || !strcmp(o, "--t") || !strcmp(o, "--placement");
        if (value && i + 1 >= argc) return cli_fail(1, "balls: %s needs a value", o);
        if (!strcmp(o, "--epsilon")) {
            /* a bad value is bad input to the approximation (FL_ERR_INPUT), as in the library */
            if (cli_parse_double(argv[++i], &a->epsilon) || !(a->epsilon > 0) ||
                !isfinite(a->epsilon))
                return cli_fail(2, "balls: --epsilon takes a finite number > 0");
            a->has_epsilon = 1;
        } else if (!strcmp(o, "--t")) {
            if (cli_parse_double(argv[++i], &a->t) || !(a->t > 0 && a->t < 1))
                return cli_fail(1, "balls: --t takes a number in (0, 1)");
        } else if (!strcmp(o, "--placement")) {
            if (cli_parse_skin_placement(argv[++i], &a->placement))
                return cli_fail(1, "balls: --placement takes alg1 or subdivision");
        } else if (o[0] == '-' && o[1]) {
            return cli_fail(1, "balls: unknown option '%s' (see --help)", o);
        } else if (!a->mesh) {
            a->mesh = o;
        } else {
            return cli_fail(1, "balls: unexpected argument '%s'", o);
        }
    }
    return 0;
}

/* B_perp as "x y z r" lines, written atomically. */
static fl_status write_xyzr(const char *path, const fl_balls *b, fl_error *err)
{
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st) return st;
    for (size_t i = 0; i < b->count; i++) {
        const double *p = b->xyzw + 4 * i;
        fprintf(out.fp, "%.17g %.17g %.17g %.17g\n", p[0], p[1], p[2], sqrt(p[3]));
    }
    return fl_out_commit(&out, err);
}

int cmd_balls(int argc, char **argv)
{
    cli_common c = {0};
    balls_args a = {0};
    int bad = parse(argc, argv, &c, &a);
    if (bad) return bad;
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    if (!a.mesh) return cli_fail(1, "balls: needs a MESH (see --help)");
    if (!a.has_epsilon) return cli_fail(1, "balls: needs --epsilon E (see --help)");
    fl_error err;
    fl_mesh mesh = {0};
    fl_skin_approx ap;
    memset(&ap, 0, sizeof ap);
    cli_progress prog;
    cli_progress_init(&prog, &c);
    double t0 = cli_now();
    fl_status st = fl_read_mesh(a.mesh, &mesh, &err);
    if (st == FL_OK) {
        fl_skin_approx_options opt = {0};
        opt.t = a.t;
        opt.placement = a.placement;
        opt.progress = cli_progress_fn;
        opt.progress_user = &prog;
        st = fl_skin_approx_build(&mesh, a.epsilon, &opt, &ap, &err);
        cli_progress_done(&prog);
    }
    double seconds = cli_now() - t0;
    if (st == FL_OK && !ap.verified)
        st = fl_fail(&err, FL_ERR_ALGORITHM, NULL, -1,
                     "balls: not verified after %d rounds (Hausdorff <= %g, Euler %lld vs %lld "
                     "of the input); try a smaller epsilon than %g",
                     ap.rounds, ap.hausdorff[1], ap.euler, ap.euler_input, a.epsilon);
    /* The union's own boundary (issue #12): certified separately from the skin of B*. */
    fl_skin_union_hausdorff_result uh;
    memset(&uh, 0, sizeof uh);
    double union_seconds = 0;
    if (st == FL_OK) {
        double t1 = cli_now();
        fl_skin_union_hausdorff_options uo = {0};
        uo.precision = a.epsilon / 50;
        uo.progress = cli_progress_fn;
        uo.progress_user = &prog;
        st = fl_skin_union_hausdorff(&ap.perp, &mesh, &uo, &uh, &err);
        cli_progress_done(&prog);
        seconds = cli_now() - t0;
        union_seconds = cli_now() - t1;
        if (st == FL_OK && !(uh.hausdorff[1] <= a.epsilon))
            st = fl_fail(&err, FL_ERR_ALGORITHM, NULL, -1,
                         "balls: the boundary of the union of B_perp is not certified within "
                         "%g of the input (Hausdorff in [%g, %g])",
                         a.epsilon, uh.hausdorff[0], uh.hausdorff[1]);
    }
    if (st == FL_OK && c.output) st = write_xyzr(c.output, &ap.perp, &err);
    if (st == FL_OK && c.json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_uint(&j, "balls", ap.perp.count);
        cli_json_uint(&j, "boundary_balls", ap.surface.count);
        cli_json_double(&j, "epsilon", a.epsilon);
        cli_json_double(&j, "hausdorff_lower", uh.hausdorff[0]);
        cli_json_double(&j, "hausdorff_upper", uh.hausdorff[1]);
        cli_json_double(&j, "skin_hausdorff_upper", ap.hausdorff[1]);
        cli_json_int(&j, "euler", ap.euler);
        cli_json_int(&j, "euler_input", ap.euler_input);
        cli_json_int(&j, "rounds", ap.rounds);
        cli_json_double(&j, "union_seconds", union_seconds);
        cli_json_double(&j, "seconds", seconds);
        cli_json_end(&j);
    } else if (st == FL_OK && !c.quiet) {
        printf("%zu balls (B_perp) from %zu surface balls approximate %s within %g (certified "
               "Hausdorff <= %g for the union, <= %g for the skin of B*, Euler %lld; %.3f s)\n",
               ap.perp.count, ap.surface.count, a.mesh, a.epsilon, uh.hausdorff[1],
               ap.hausdorff[1], ap.euler, seconds);
    }
    fl_skin_approx_free(&ap);
    fl_mesh_free(&mesh);
    return st == FL_OK ? 0 : cli_report(&err);
}

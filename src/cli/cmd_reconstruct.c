/* flintstone reconstruct POINTS [-o OUT] [--criterion C] [--keep EDGES] [--extra N]
 * The boundary through every point by constriction of the Delaunay triangulation (thesis
 * ch. 5): a simple polygon for 2D points. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

static const char *usage_text =
    "usage: flintstone reconstruct POINTS [-o OUT] [--criterion C] [--keep EDGES] [--extra N]\n"
    "                              [--json] [--quiet]\n"
    "\n"
    "Constructs the closed boundary through every point (thesis ch. 5): for 2D points a simple\n"
    "polygon, by constricting the Delaunay triangulation from the convex hull inward. When the\n"
    "triangulation locks (non-Hamiltonian), extra edges of γ([-1,1],[c0,1]) are added for\n"
    "decreasing c0 < 0; the c0 needed is reported. Exits 3 with the reason when some points\n"
    "cannot be brought onto the boundary (the polygon is still written).\n"
    "\n"
    "  --criterion C  gamma (default, γ-indicator Def. 5.1) | area-change | voronoi-skeleton\n"
    "  --keep EDGES   a text file of 'i j' lines (0-based point indices): edges that must be\n"
    "                 on the boundary (constrained constriction, §5.7)\n"
    "  --extra N      augmentation in N steps of c0 (default 10: c0 = -0.1, ..., -1);\n"
    "                 a negative N disables augmentation\n"
    "  -o OUT         .xy | .geojson (the polygon) | .svg (points, Delaunay faint, boundary\n"
    "                 bold) | .off (interior triangles)\n"
    "  --json         dim, points, boundary_vertices, all_on_boundary, simple, augmented_c0,\n"
    "                 area, seconds\n"
    "\n"
    "example: flintstone reconstruct data/demo/leaf.xy -o leaf.svg --json\n";

typedef struct rec_args {
    const char *input, *criterion, *keep;
    long extra;
    int has_extra;
} rec_args;

static int parse(int argc, char **argv, cli_common *c, rec_args *a)
{
    for (int i = 1; i < argc; i++) {
        int k = cli_common_option(c, argc, argv, &i);
        if (k < 0) return 1;
        if (k > 0) continue;
        const char *opt = argv[i];
        int takes =
            !strcmp(opt, "--criterion") || !strcmp(opt, "--keep") || !strcmp(opt, "--extra");
        if (takes && i + 1 >= argc) return cli_fail(1, "reconstruct: %s needs a value", opt);
        if (!strcmp(opt, "--criterion")) {
            a->criterion = argv[++i];
        } else if (!strcmp(opt, "--keep")) {
            a->keep = argv[++i];
        } else if (!strcmp(opt, "--extra")) {
            char *end;
            a->extra = strtol(argv[++i], &end, 10);
            if (*end || end == argv[i] || labs(a->extra) > 1000000)
                return cli_fail(1, "reconstruct: --extra takes a whole number, got '%s'", argv[i]);
            a->has_extra = 1;
        } else if (opt[0] == '-' && opt[1]) {
            return cli_fail(1, "reconstruct: unknown option '%s' (see --help)", opt);
        } else if (a->input) {
            return cli_fail(1, "reconstruct: one input file, got '%s' and '%s'", a->input, opt);
        } else {
            a->input = opt;
        }
    }
    return 0;
}

/* Kept edges: 'i j' lines read with the point reader (2 numbers a line), each a whole number
 * that fits an index. Range checks against the point count are the library's. */
static fl_status read_keep(const char *path, uint32_t **pairs, size_t *count, fl_error *err)
{
    fl_points p;
    fl_status st = fl_read_points(path, &p, err);
    if (st) return st;
    if (p.dim != 2) {
        fl_points_free(&p);
        return fl_fail(err, FL_ERR_INPUT, path, -1, "kept edges need 2 indices a line ('i j')");
    }
    *pairs = fl_alloc_array(2 * p.count, sizeof(uint32_t));
    if (!*pairs) st = fl_fail(err, FL_ERR_NOMEM, path, -1, "out of memory");
    for (size_t i = 0; st == FL_OK && i < 2 * p.count; i++) {
        double v = p.coords[i];
        if (v < 0 || v > 4294967294.0 || v != floor(v))
            st = fl_fail(err, FL_ERR_INPUT, path, (long)(i / 2) + 1,
                         "'%.17g' is not a point index (a whole number >= 0)", v);
        else
            (*pairs)[i] = (uint32_t)v;
    }
    *count = p.count;
    fl_points_free(&p);
    if (st) {
        free(*pairs);
        *pairs = NULL;
    }
    return st;
}

static void print_2d(const cli_common *c, const fl_reconstruction2 *r, double seconds)
{
    if (c->json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_int(&j, "dim", 2);
        cli_json_uint(&j, "points", r->point_count);
        cli_json_uint(&j, "boundary_vertices", r->boundary_count);
        cli_json_bool(&j, "all_on_boundary", r->all_on_boundary);
        cli_json_bool(&j, "simple", 1); /* by construction: the boundary of a triangulated disc */
        if (isnan(r->augmented_c0))
            cli_json_null(&j, "augmented_c0");
        else
            cli_json_double(&j, "augmented_c0", r->augmented_c0);
        cli_json_double(&j, "area", r->area);
        if (!r->all_on_boundary) cli_json_string(&j, "reason", r->reason);
        cli_json_double(&j, "seconds", seconds);
        cli_json_end(&j);
        return;
    }
    if (c->quiet) return;
    printf("2D boundary: %zu of %zu distinct points on a simple polygon, area %.6g",
           r->boundary_count, r->unique_count, r->area);
    if (!isnan(r->augmented_c0)) printf(", augmented to c0 = %g", r->augmented_c0);
    printf(" (%.3f s)\n", seconds);
}

static int run_2d(const cli_common *c, const rec_args *a, const fl_points *p, double t0)
{
    fl_error err;
    fl_reconstruct2_options opt = {0};
    if (a->criterion && fl_reconstruct2_criterion_parse(a->criterion, &opt.criterion, &err))
        return cli_report(&err);
    uint32_t *keep = NULL;
    if (a->keep && read_keep(a->keep, &keep, &opt.keep_count, &err)) return cli_report(&err);
    opt.keep = keep;
    opt.extra_levels = a->has_extra ? (int)a->extra : 0;
    cli_progress prog;
    cli_progress_init(&prog, c);
    opt.progress = cli_progress_fn;
    opt.progress_user = &prog;
    fl_reconstruction2 r = {0};
    fl_status st = fl_reconstruct2(p->coords, p->count, &opt, &r, &err);
    cli_progress_done(&prog);
    free(keep);
    if (st == FL_OK && c->output)
        st = fl_write_reconstruction2(c->output, p->coords, p->count, &r, &err);
    if (st) {
        fl_reconstruction2_free(&r);
        return cli_report(&err);
    }
    print_2d(c, &r, cli_now() - t0);
    int code = 0;
    if (!r.all_on_boundary)
        code = cli_fail(3, "%s: not every point is on the boundary: %s", a->input, r.reason);
    fl_reconstruction2_free(&r);
    return code;
}

int cmd_reconstruct(int argc, char **argv)
{
    cli_common c = {0};
    rec_args a = {0};
    if (parse(argc, argv, &c, &a)) return 1;
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    if (!a.input) return cli_fail(1, "reconstruct: no input file (see --help)");
    fl_error err;
    fl_points p;
    double t0 = cli_now();
    if (fl_read_points(a.input, &p, &err)) return cli_report(&err);
    int code;
    if (p.dim == 2)
        code = run_2d(&c, &a, &p, t0);
    else
        code = cli_fail(3, "reconstruct: %s holds 3D points; 3D constriction is not available yet",
                        a.input);
    fl_points_free(&p);
    return code;
}

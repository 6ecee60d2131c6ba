/* flintstone reconstruct POINTS [-o OUT] [--criterion C] [--keep EDGES] [--extra N]
 * The boundary through every point by constriction of the Delaunay triangulation (thesis
 * ch. 5): a simple polygon for 2D points, a closed genus-0 mesh for 3D points. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

static const char *usage_text =
    "usage: flintstone reconstruct POINTS [-o OUT] [--criterion C] [--keep FILE] [--extra N]\n"
    "                              [--no-augment] [--json] [--quiet]\n"
    "\n"
    "Constructs the closed boundary through every point (thesis ch. 5) by constricting the\n"
    "Delaunay triangulation from the convex hull inward: for 2D points a simple polygon, for 3D\n"
    "points a closed genus-0 triangle mesh. In 2D, when the triangulation locks\n"
    "(non-Hamiltonian), extra edges of γ([-1,1],[c0,1]) are added for decreasing c0 < 0 and the\n"
    "c0 needed is reported; in 3D, 2-3 flips bring overlapping tetrahedra of γ([-1,1],[c0,1])\n"
    "into the region (§5.4). Exits 3 with the reason when some points (or kept faces) cannot be\n"
    "brought onto the boundary (the result is still written).\n"
    "\n"
    "  --criterion C  gamma (default, γ-indicator Def. 5.1/5.2) | area-change |\n"
    "                 voronoi-skeleton (2D only)\n"
    "  --keep FILE    2D: 'i j' lines, edges; 3D: 'i j k' lines, triangles (0-based point\n"
    "                 indices) that must be on the boundary (constrained constriction, §5.7);\n"
    "                 a 3D triangle must be a face of the Delaunay tetrahedralization\n"
    "  --extra N      2D: augmentation in N steps of c0 (default 10: c0 = -0.1, ..., -1),\n"
    "                 a negative N disables it; 3D: remove N more tetrahedra once every\n"
    "                 point is on the boundary (thesis Fig. 5.5)\n"
    "  --no-augment   3D: when constriction locks, stop (no unlocking flips)\n"
    "  -o OUT         .xy | .geojson (the polygon) | .svg (points, Delaunay faint, boundary\n"
    "                 bold) | .off (interior triangles); 3D: .off .obj .ply .stl (boundary)\n"
    "  --json         dim, points, boundary_vertices, all_on_boundary, augmented_c0, seconds;\n"
    "                 2D: simple, area; 3D: faces, closed, manifold, genus, volume, flips,\n"
    "                 keep_missing\n"
    "\n"
    "example: flintstone reconstruct data/demo/leaf.xy -o leaf.svg --json\n";

typedef struct rec_args {
    const char *input, *criterion, *keep;
    long extra;
    int has_extra, no_augment;
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
        } else if (!strcmp(opt, "--no-augment")) {
            a->no_augment = 1;
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

/* Kept edges ('i j' lines, dim 2) or triangles ('i j k', dim 3) read with the point reader,
 * each number a whole number that fits an index. Range checks against the point count are the
 * library's. */
static fl_status read_keep(const char *path, int dim, uint32_t **pairs, size_t *count,
                           fl_error *err)
{
    fl_points p;
    fl_status st = fl_read_points(path, &p, err);
    if (st) return st;
    if (p.dim != dim) {
        fl_points_free(&p);
        return fl_fail(err, FL_ERR_INPUT, path, -1, "%s",
                       dim == 2 ? "kept edges need 2 indices a line ('i j')"
                                : "kept triangles need 3 indices a line ('i j k')");
    }
    *pairs = fl_alloc_array((size_t)dim * p.count, sizeof(uint32_t));
    if (!*pairs) st = fl_fail(err, FL_ERR_NOMEM, path, -1, "out of memory");
    for (size_t i = 0; st == FL_OK && i < (size_t)dim * p.count; i++) {
        double v = p.coords[i];
        if (v < 0 || v > 4294967294.0 || v != floor(v))
            st = fl_fail(err, FL_ERR_INPUT, path, (long)(i / (size_t)dim) + 1,
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
    if (a->no_augment)
        return cli_fail(1, "reconstruct: --no-augment is for 3D points (2D: --extra -1)");
    fl_error err;
    fl_reconstruct2_options opt = {0};
    if (a->criterion && fl_reconstruct2_criterion_parse(a->criterion, &opt.criterion, &err))
        return cli_report(&err);
    uint32_t *keep = NULL;
    if (a->keep && read_keep(a->keep, 2, &keep, &opt.keep_count, &err)) return cli_report(&err);
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

static int criterion3(const char *text, fl_reconstruct3_criterion *c)
{
    if (!text || !strcmp(text, "gamma"))
        *c = FL_RECONSTRUCT3_GAMMA;
    else if (!strcmp(text, "area-change"))
        *c = FL_RECONSTRUCT3_AREA_CHANGE;
    else
        return cli_fail(1, "reconstruct: 3D criterion is gamma or area-change, got '%s'", text);
    return 0;
}

/* The boundary is checked again by fl_mesh_check, an independent reading of the same triangles,
 * so closed / manifold / genus in the summary are measured, not assumed. */
static void print_3d(const cli_common *c, const fl_reconstruction3 *r, const fl_mesh_report *m,
                     double seconds)
{
    if (c->json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_int(&j, "dim", 3);
        cli_json_uint(&j, "points", r->point_count);
        cli_json_uint(&j, "boundary_vertices", r->boundary_vertex_count);
        cli_json_bool(&j, "all_on_boundary", r->all_on_boundary);
        cli_json_uint(&j, "points_inside", r->points_inside);
        cli_json_uint(&j, "faces", r->triangle_count);
        cli_json_bool(&j, "closed", m->closed);
        cli_json_bool(&j, "manifold", m->manifold);
        if (m->genus >= 0)
            cli_json_int(&j, "genus", m->genus);
        else
            cli_json_null(&j, "genus");
        if (isnan(r->augmented_c0))
            cli_json_null(&j, "augmented_c0");
        else
            cli_json_double(&j, "augmented_c0", r->augmented_c0);
        cli_json_double(&j, "volume", r->volume);
        cli_json_uint(&j, "flips", r->flip_count);
        cli_json_uint(&j, "keep_missing", r->keep_missing);
        if (!r->all_on_boundary) cli_json_string(&j, "reason", r->reason);
        cli_json_double(&j, "seconds", seconds);
        cli_json_end(&j);
        return;
    }
    if (c->quiet) return;
    printf("3D boundary: %zu of %zu distinct points on %zu triangles (%s, %s, genus %lld), "
           "volume %.6g (%.3f s)\n",
           r->boundary_vertex_count, r->unique_count, r->triangle_count,
           m->closed ? "closed" : "NOT closed", m->manifold ? "manifold" : "NOT manifold", m->genus,
           r->volume, seconds);
}

static int run_3d(const cli_common *c, const rec_args *a, const fl_points *p, double t0)
{
    fl_reconstruct3_options opt = {0};
    if (criterion3(a->criterion, &opt.criterion)) return 1;
    if (a->has_extra && a->extra < 0) return cli_fail(1, "reconstruct: --extra must be >= 0 in 3D");
    opt.extra = a->has_extra ? (size_t)a->extra : 0;
    opt.no_augment = a->no_augment;
    fl_error err;
    uint32_t *keep = NULL;
    if (a->keep && read_keep(a->keep, 3, &keep, &opt.keep_count, &err)) return cli_report(&err);
    opt.keep = keep;
    cli_progress prog;
    cli_progress_init(&prog, c);
    opt.progress = cli_progress_fn;
    opt.progress_user = &prog;
    fl_reconstruction3 r = {0};
    fl_status st = fl_reconstruct3(p->coords, p->count, &opt, &r, &err);
    free(keep);
    cli_progress_done(&prog);
    fl_mesh mesh = {p->count, p->coords, r.triangle_count, r.tri};
    fl_mesh_report m = {0};
    fl_mesh_check_options mopt = {.skip_self_intersections = 1};
    if (st == FL_OK) st = fl_mesh_check(&mesh, &mopt, &m, &err);
    if (st == FL_OK && c->output) st = fl_write_mesh(c->output, &mesh, &err);
    if (st) {
        fl_mesh_report_free(&m);
        fl_reconstruction3_free(&r);
        return cli_report(&err);
    }
    print_3d(c, &r, &m, cli_now() - t0);
    int code = 0;
    if (!r.all_on_boundary)
        code = cli_fail(3, "%s: %zu points (and %zu kept triangles) are not on the boundary: %s",
                        a->input, r.points_inside, r.keep_missing, r.reason);
    fl_mesh_report_free(&m);
    fl_reconstruction3_free(&r);
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
    int code = cli_check_output(c.output, p.dim == 2 ? "xy geojson json svg off" : "off obj ply stl");
    if (!code) code = p.dim == 2 ? run_2d(&c, &a, &p, t0) : run_3d(&c, &a, &p, t0);
    fl_points_free(&p);
    return code;
}

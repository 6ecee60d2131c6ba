/* flintstone delaunay POINTS [-o OUT] [--weighted] [--verify] [--json]
 * 2D points give the Delaunay triangulation (.off or .svg out), 3D points the Delaunay
 * tetrahedralization (.vtk or .node/.ele out), and --weighted reads x y z w balls for the regular
 * triangulation. */
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

static const char *usage_text =
    "usage: flintstone delaunay POINTS [-o OUT] [--weighted] [--verify] [--json] [--quiet]\n"
    "\n"
    "Delaunay triangulation of 2D points, Delaunay tetrahedralization of 3D points, or with\n"
    "--weighted the regular triangulation of balls given as 'x y z w' lines (w = squared radius).\n"
    "Duplicate points are merged and counted; all-collinear (2D) or all-coplanar (3D) input\n"
    "exits 3 with an explanation.\n"
    "\n"
    "  -o OUT      2D: .svg (picture) or .off .obj .ply .stl (triangles, z = 0);\n"
    "              3D: .vtk or .node/.ele\n"
    "  --weighted  POINTS holds 4 numbers a line: x y z w\n"
    "  --verify    check orientation, adjacency, Euler relation and the empty-sphere (power)\n"
    "              property of every simplex with exact predicates; exit 3 if any fails\n"
    "  --json      print one JSON object: dim, points, unique_points, simplices, hull_faces,\n"
    "              hidden (weighted), valid (with --verify), seconds\n"
    "\n"
    "example: flintstone delaunay data/demo/peanut.xyz -o peanut.vtk --verify --json\n";

typedef struct dt_summary {
    int dim, weighted, verified, valid;
    size_t points, unique_points, simplices, hull_faces, hidden;
    double seconds;
} dt_summary;

static void print_summary(const cli_common *c, const dt_summary *s)
{
    if (c->json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_int(&j, "dim", s->dim);
        cli_json_bool(&j, "weighted", s->weighted);
        cli_json_uint(&j, "points", s->points);
        cli_json_uint(&j, "unique_points", s->unique_points);
        cli_json_uint(&j, "simplices", s->simplices);
        cli_json_uint(&j, "hull_faces", s->hull_faces);
        if (s->weighted) cli_json_uint(&j, "hidden", s->hidden);
        if (s->verified) cli_json_bool(&j, "valid", s->valid);
        cli_json_double(&j, "seconds", s->seconds);
        cli_json_end(&j);
        return;
    }
    printf("%dD %s: %zu points (%zu distinct), %zu %s, %zu hull %s", s->dim,
           s->weighted ? "regular triangulation" : "Delaunay", s->points, s->unique_points,
           s->simplices, s->dim == 2 ? "triangles" : "tetrahedra", s->hull_faces,
           s->dim == 2 ? "edges" : "faces");
    if (s->weighted) printf(", %zu hidden", s->hidden);
    if (s->verified) printf(", verified %s", s->valid ? "valid" : "INVALID");
    printf(" (%.3f s)\n", s->seconds);
}

/* The edges of a 2D triangulation as a graph, for the SVG picture: each interior edge once
 * (from the triangle with the lower index), each hull edge once. */
static fl_status write_dt2_svg(const char *path, const fl_points *p, const fl_dt2 *dt,
                               fl_error *err)
{
    fl_graph g = {2,   p->count, 2, 0, fl_alloc_array(6 * dt->triangle_count + 1, sizeof(uint32_t)),
                  NULL};
    if (!g.simplices) return fl_fail(err, FL_ERR_NOMEM, path, -1, "out of memory");
    for (size_t t = 0; t < dt->triangle_count; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t nb = dt->adj[3 * t + k];
            if (nb != UINT32_MAX && nb < t) continue;
            uint32_t a = dt->tri[3 * t + (k + 1) % 3], b = dt->tri[3 * t + (k + 2) % 3];
            g.simplices[2 * g.simplex_count] = a < b ? a : b;
            g.simplices[2 * g.simplex_count + 1] = a < b ? b : a;
            g.simplex_count++;
        }
    fl_status st = fl_write_graph(path, p->coords, p->count, &g, err);
    fl_graph_free(&g);
    return st;
}

/* Writes a 2D triangulation: .svg as a picture of its edges, any mesh format as a flat mesh
 * (z = 0). */
fl_status cli_write_dt2(const char *path, const fl_points *p, const fl_dt2 *dt, fl_error *err)
{
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    if (strcmp(ext, "svg") == 0) return write_dt2_svg(path, p, dt, err);
    fl_mesh m = {0};
    m.vertex_count = p->count;
    m.xyz = fl_alloc_array(3 * p->count + 1, sizeof(double));
    if (!m.xyz) return fl_fail(err, FL_ERR_NOMEM, path, -1, "out of memory");
    for (size_t i = 0; i < p->count; i++) {
        m.xyz[3 * i] = p->coords[2 * i];
        m.xyz[3 * i + 1] = p->coords[2 * i + 1];
        m.xyz[3 * i + 2] = 0;
    }
    m.triangle_count = dt->triangle_count;
    m.tri = dt->tri;
    fl_status st = fl_write_mesh(path, &m, err);
    free(m.xyz);
    return st;
}

static int run_2d(const cli_common *c, const fl_points *p, int verify, cli_progress *prog,
                  dt_summary *s)
{
    fl_error err;
    fl_dt2 dt = {0};
    fl_dt2_options opt = {cli_progress_fn, prog, 0};
    fl_status st = fl_dt2_build(p->coords, p->count, &opt, &dt, &err);
    cli_progress_done(prog);
    if (st) return cli_report(&err);
    s->unique_points = dt.unique_count;
    s->simplices = dt.triangle_count;
    s->hull_faces = dt.hull_count;
    if (verify) {
        s->verified = 1;
        s->valid = fl_dt2_verify(p->coords, &dt, &err) == FL_OK;
        if (!s->valid) cli_report(&err);
    }
    if (c->output && (st = cli_write_dt2(c->output, p, &dt, &err))) {
        fl_dt2_free(&dt);
        return cli_report(&err);
    }
    fl_dt2_free(&dt);
    return 0;
}

static int run_3d(const cli_common *c, const fl_points *p, int verify, cli_progress *prog,
                  dt_summary *s)
{
    fl_error err;
    fl_dt3 dt = {0};
    fl_dt3_options opt = {cli_progress_fn, prog, 0};
    fl_status st = fl_dt3_build(p->coords, p->count, &opt, &dt, &err);
    cli_progress_done(prog);
    if (st) return cli_report(&err);
    s->unique_points = dt.unique_count;
    s->simplices = dt.tet_count;
    s->hull_faces = dt.hull_face_count;
    if (verify) {
        s->verified = 1;
        s->valid = fl_dt3_verify(p->coords, &dt, &err) == FL_OK;
        if (!s->valid) cli_report(&err);
    }
    if (c->output &&
        (st = fl_write_tets(c->output, p->coords, p->count, dt.tet, dt.tet_count, &err))) {
        fl_dt3_free(&dt);
        return cli_report(&err);
    }
    fl_dt3_free(&dt);
    return 0;
}

static int run_weighted(const cli_common *c, const fl_balls *b, int verify, cli_progress *prog,
                        dt_summary *s)
{
    fl_error err;
    fl_rt3 rt = {0};
    fl_rt3_options opt = {cli_progress_fn, prog, 0};
    fl_status st = fl_rt3_build(b->xyzw, b->count, &opt, &rt, &err);
    cli_progress_done(prog);
    if (st) return cli_report(&err);
    s->unique_points = rt.vertex_count;
    s->simplices = rt.tet_count;
    s->hull_faces = rt.hull_face_count;
    s->hidden = rt.hidden_count;
    if (verify) {
        s->verified = 1;
        s->valid = fl_rt3_verify(b->xyzw, &rt, &err) == FL_OK;
        if (!s->valid) cli_report(&err);
    }
    int code = 0;
    if (c->output) {
        double *xyz = malloc(3 * b->count * sizeof(double) + 1);
        if (!xyz) {
            fl_rt3_free(&rt);
            cli_fail(3, "out of memory");
            cli_memory_limit_note();
            return 3;
        }
        for (size_t i = 0; i < b->count; i++)
            memcpy(xyz + 3 * i, b->xyzw + 4 * i, 3 * sizeof(double));
        if ((st = fl_write_tets(c->output, xyz, b->count, rt.tet, rt.tet_count, &err)))
            code = cli_report(&err);
        free(xyz);
    }
    fl_rt3_free(&rt);
    return code;
}

int cmd_delaunay(int argc, char **argv)
{
    cli_common c = {0};
    const char *input = NULL;
    int weighted = 0, verify = 0;
    for (int i = 1; i < argc; i++) {
        int k = cli_common_option(&c, argc, argv, &i);
        if (k < 0) return 1;
        if (k > 0) continue;
        if (strcmp(argv[i], "--weighted") == 0)
            weighted = 1;
        else if (strcmp(argv[i], "--verify") == 0)
            verify = 1;
        else if (argv[i][0] == '-' && argv[i][1])
            return cli_fail(1, "delaunay: unknown option '%s' (see flintstone delaunay --help)",
                            argv[i]);
        else if (input)
            return cli_fail(1, "delaunay: one input file, got '%s' and '%s'", input, argv[i]);
        else
            input = argv[i];
    }
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    if (!input) return cli_fail(1, "delaunay: no input file (see flintstone delaunay --help)");

    fl_error err;
    dt_summary s = {0};
    cli_progress prog;
    cli_progress_init(&prog, &c);
    double t0 = cli_now();
    int code;
    s.weighted = weighted;
    if (weighted) {
        fl_balls b;
        if ((code = cli_check_output(c.output, "vtk node ele"))) return code;
        if (fl_read_balls(input, &b, &err)) return cli_report(&err);
        s.dim = 3;
        s.points = b.count;
        code = run_weighted(&c, &b, verify, &prog, &s);
        fl_balls_free(&b);
    } else {
        fl_points p;
        if (fl_read_points(input, &p, &err)) return cli_report(&err);
        if ((code = cli_check_output(c.output, p.dim == 2 ? "svg off obj ply stl"
                                                          : "vtk node ele"))) {
            fl_points_free(&p);
            return code;
        }
        s.dim = p.dim;
        s.points = p.count;
        code = p.dim == 2 ? run_2d(&c, &p, verify, &prog, &s) : run_3d(&c, &p, verify, &prog, &s);
        fl_points_free(&p);
    }
    if (code) return code;
    s.seconds = cli_now() - t0;
    print_summary(&c, &s);
    return s.verified && !s.valid ? 3 : 0;
}

/* flintstone demo: the main job on the bundled default inputs (data/demo, our own synthetic
 * shapes). Each step runs a capability through the library, writes its output into the demo
 * directory and adds its key numbers to summary.json. The pipeline grows as capabilities land
 * (reconstruction, flintstones, Meshsweeper, G1 surfaces, skins). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

#ifndef FL_DATA_DIR
#define FL_DATA_DIR "data/demo"
#endif

static const char *usage_text =
    "usage: flintstone demo [--data DIR] [--out DIR] [--json] [--quiet]\n"
    "\n"
    "Runs the pipeline on the bundled inputs (a torus mesh, 160 points on a closed 2D curve,\n"
    "1500 points on a closed surface): mesh check, 2D and 3D Delaunay triangulations verified\n"
    "with exact predicates, the 2D and 3D boundaries by constriction. Writes the outputs and\n"
    "summary.json into the output directory.\n"
    "\n"
    "  --data DIR  where the bundled inputs are (default: the source tree's data/demo, then\n"
    "              ./data/demo)\n"
    "  --out DIR   output directory (default: demo-out)\n"
    "\n"
    "example: flintstone demo --out /tmp/demo\n";

typedef struct demo {
    const char *data_dir, *out_dir;
    cli_json json; /* summary.json, written into a temporary and renamed at the end */
    fl_out_file summary;
    int failed;
    int quiet;
} demo;

static void path_in(char *buf, size_t size, const char *dir, const char *name)
{
    snprintf(buf, size, "%s/%s", dir, name);
}

static int step_failed(demo *d, const char *step, const fl_error *err)
{
    char buf[1200];
    fl_error_format(err, buf, sizeof buf);
    fprintf(stderr, "flintstone: error: demo step '%s': %s\n", step, buf);
    d->failed = cli_exit_code(err->status);
    return d->failed;
}

static int step_check(demo *d)
{
    char in[1024];
    fl_error err;
    fl_mesh mesh;
    fl_mesh_report r;
    path_in(in, sizeof in, d->data_dir, "torus.off");
    double t0 = cli_now();
    if (fl_read_mesh(in, &mesh, &err)) return step_failed(d, "check", &err);
    fl_status st = fl_mesh_check(&mesh, NULL, &r, &err);
    fl_mesh_free(&mesh);
    if (st) return step_failed(d, "check", &err);
    cli_json *j = &d->json;
    cli_json_open_object(j, "check");
    cli_json_string(j, "input", in);
    cli_json_uint(j, "vertices", r.vertices);
    cli_json_uint(j, "faces", r.faces);
    cli_json_bool(j, "closed", r.closed);
    cli_json_bool(j, "manifold", r.manifold);
    cli_json_bool(j, "oriented", r.oriented);
    cli_json_int(j, "genus", r.genus);
    cli_json_uint(j, "self_intersections", r.self_intersections);
    cli_json_double(j, "volume", r.volume);
    cli_json_double(j, "seconds", cli_now() - t0);
    cli_json_close(j);
    if (!d->quiet)
        printf("check     %s: %zu faces, %s, genus %lld, %zu self-intersections, volume %.4g\n", in,
               r.faces, r.closed && r.manifold ? "closed manifold" : "NOT a closed manifold",
               r.genus, r.self_intersections, r.volume);
    fl_mesh_report_free(&r);
    return 0;
}

static int step_delaunay2(demo *d)
{
    char in[1024], out[1024];
    fl_error err;
    fl_points p;
    fl_dt2 dt = {0};
    path_in(in, sizeof in, d->data_dir, "leaf.xy");
    path_in(out, sizeof out, d->out_dir, "leaf-delaunay.off");
    double t0 = cli_now();
    if (fl_read_points(in, &p, &err)) return step_failed(d, "delaunay 2d", &err);
    fl_status st = fl_dt2_build(p.coords, p.count, NULL, &dt, &err);
    int valid = st == FL_OK && fl_dt2_verify(p.coords, &dt, &err) == FL_OK;
    if (valid) st = cli_write_dt2(out, &p, &dt, &err);
    double seconds = cli_now() - t0;
    fl_points_free(&p);
    if (st || !valid) {
        fl_dt2_free(&dt);
        return step_failed(d, "delaunay 2d", &err);
    }
    cli_json *j = &d->json;
    cli_json_open_object(j, "delaunay_2d");
    cli_json_string(j, "input", in);
    cli_json_string(j, "output", out);
    cli_json_uint(j, "points", dt.point_count);
    cli_json_uint(j, "triangles", dt.triangle_count);
    cli_json_uint(j, "hull_edges", dt.hull_count);
    cli_json_bool(j, "valid", valid);
    cli_json_double(j, "seconds", seconds);
    cli_json_close(j);
    if (!d->quiet)
        printf("delaunay  %s: %zu points, %zu triangles, verified -> %s\n", in, dt.point_count,
               dt.triangle_count, out);
    fl_dt2_free(&dt);
    return 0;
}

/* The leaf's scattered points back to a closed boundary (thesis ch. 5). */
static int step_reconstruct2(demo *d)
{
    char in[1024], out[1024];
    fl_error err;
    fl_points p;
    fl_reconstruction2 rec = {0};
    path_in(in, sizeof in, d->data_dir, "leaf.xy");
    path_in(out, sizeof out, d->out_dir, "leaf-boundary.svg");
    double t0 = cli_now();
    if (fl_read_points(in, &p, &err)) return step_failed(d, "reconstruct 2d", &err);
    fl_status st = fl_reconstruct2(p.coords, p.count, NULL, &rec, &err);
    if (st == FL_OK) st = fl_write_reconstruction2(out, p.coords, p.count, &rec, &err);
    double seconds = cli_now() - t0;
    fl_points_free(&p);
    if (st) {
        fl_reconstruction2_free(&rec);
        return step_failed(d, "reconstruct 2d", &err);
    }
    cli_json *j = &d->json;
    cli_json_open_object(j, "reconstruct_2d");
    cli_json_string(j, "input", in);
    cli_json_string(j, "output", out);
    cli_json_uint(j, "points", rec.point_count);
    cli_json_uint(j, "boundary_vertices", rec.boundary_count);
    cli_json_bool(j, "all_on_boundary", rec.all_on_boundary);
    cli_json_double(j, "area", rec.area);
    cli_json_double(j, "seconds", seconds);
    cli_json_close(j);
    if (!d->quiet)
        printf("boundary  %s: %zu of %zu points on a simple polygon, area %.4g -> %s\n", in,
               rec.boundary_count, rec.unique_count, rec.area, out);
    fl_reconstruction2_free(&rec);
    return 0;
}

static int step_delaunay3(demo *d)
{
    char in[1024], out[1024];
    fl_error err;
    fl_points p;
    fl_dt3 dt = {0};
    path_in(in, sizeof in, d->data_dir, "peanut.xyz");
    path_in(out, sizeof out, d->out_dir, "peanut-delaunay.vtk");
    double t0 = cli_now();
    if (fl_read_points(in, &p, &err)) return step_failed(d, "delaunay 3d", &err);
    fl_status st = fl_dt3_build(p.coords, p.count, NULL, &dt, &err);
    int valid = st == FL_OK && fl_dt3_verify(p.coords, &dt, &err) == FL_OK;
    if (valid) st = fl_write_tets(out, p.coords, p.count, dt.tet, dt.tet_count, &err);
    double seconds = cli_now() - t0;
    fl_points_free(&p);
    if (st || !valid) {
        fl_dt3_free(&dt);
        return step_failed(d, "delaunay 3d", &err);
    }
    cli_json *j = &d->json;
    cli_json_open_object(j, "delaunay_3d");
    cli_json_string(j, "input", in);
    cli_json_string(j, "output", out);
    cli_json_uint(j, "points", dt.point_count);
    cli_json_uint(j, "tetrahedra", dt.tet_count);
    cli_json_uint(j, "hull_faces", dt.hull_face_count);
    cli_json_bool(j, "valid", valid);
    cli_json_double(j, "seconds", seconds);
    cli_json_close(j);
    if (!d->quiet)
        printf("delaunay  %s: %zu points, %zu tetrahedra, verified -> %s\n", in, dt.point_count,
               dt.tet_count, out);
    fl_dt3_free(&dt);
    return 0;
}

/* The peanut's scattered points back to a closed genus-0 surface, checked independently. */
static int step_reconstruct3(demo *d)
{
    char in[1024], out[1024];
    fl_error err;
    fl_points p;
    fl_reconstruction3 rec = {0};
    fl_mesh_report m = {0};
    path_in(in, sizeof in, d->data_dir, "peanut.xyz");
    path_in(out, sizeof out, d->out_dir, "peanut-boundary.off");
    double t0 = cli_now();
    if (fl_read_points(in, &p, &err)) return step_failed(d, "reconstruct 3d", &err);
    fl_status st = fl_reconstruct3(p.coords, p.count, NULL, &rec, &err);
    fl_mesh mesh = {p.count, p.coords, rec.triangle_count, rec.tri};
    if (st == FL_OK) st = fl_mesh_check(&mesh, NULL, &m, &err);
    if (st == FL_OK) st = fl_write_mesh(out, &mesh, &err);
    double seconds = cli_now() - t0;
    fl_points_free(&p);
    if (st) {
        fl_mesh_report_free(&m);
        fl_reconstruction3_free(&rec);
        return step_failed(d, "reconstruct 3d", &err);
    }
    cli_json *j = &d->json;
    cli_json_open_object(j, "reconstruct_3d");
    cli_json_string(j, "input", in);
    cli_json_string(j, "output", out);
    cli_json_uint(j, "points", rec.point_count);
    cli_json_uint(j, "boundary_vertices", rec.boundary_vertex_count);
    cli_json_bool(j, "all_on_boundary", rec.all_on_boundary);
    cli_json_uint(j, "faces", rec.triangle_count);
    cli_json_bool(j, "closed", m.closed);
    cli_json_bool(j, "manifold", m.manifold);
    cli_json_int(j, "genus", m.genus);
    cli_json_uint(j, "self_intersections", m.self_intersections);
    cli_json_double(j, "volume", rec.volume);
    cli_json_double(j, "seconds", seconds);
    cli_json_close(j);
    if (!d->quiet)
        printf("boundary  %s: %zu of %zu points on %zu triangles, %s, genus %lld -> %s\n", in,
               rec.boundary_vertex_count, rec.unique_count, rec.triangle_count,
               m.closed && m.manifold ? "closed manifold" : "NOT a closed manifold", m.genus, out);
    fl_mesh_report_free(&m);
    fl_reconstruction3_free(&rec);
    return 0;
}

/* The bundled inputs live in the source tree; a relocated binary finds them in ./data/demo. */
static const char *find_data_dir(void)
{
    struct stat st;
    if (stat(FL_DATA_DIR "/torus.off", &st) == 0) return FL_DATA_DIR;
    return "data/demo";
}

static int parse_args(int argc, char **argv, cli_common *c, demo *d)
{
    for (int i = 1; i < argc; i++) {
        int k = cli_common_option(c, argc, argv, &i);
        if (k < 0) return 1;
        if (k > 0) continue;
        int is_data = strcmp(argv[i], "--data") == 0, is_out = strcmp(argv[i], "--out") == 0;
        if ((is_data || is_out) && i + 1 >= argc)
            return cli_fail(1, "demo: %s needs a directory", argv[i]);
        if (is_data)
            d->data_dir = argv[++i];
        else if (is_out)
            d->out_dir = argv[++i];
        else
            return cli_fail(1, "demo: unexpected argument '%s' (see flintstone demo --help)",
                            argv[i]);
    }
    if (c->output) d->out_dir = c->output;
    return 0;
}

int cmd_demo(int argc, char **argv)
{
    cli_common c = {0};
    demo d = {find_data_dir(), "demo-out", {0}, {0}, 0, 0};
    if (parse_args(argc, argv, &c, &d)) return 1;
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    d.quiet = c.quiet || c.json;
    if (mkdir(d.out_dir, 0777) != 0 && errno != EEXIST)
        return cli_fail(4, "demo: cannot create output directory '%s': %s", d.out_dir,
                        strerror(errno));
    char summary[1024];
    fl_error err;
    path_in(summary, sizeof summary, d.out_dir, "summary.json");
    if (fl_out_open(&d.summary, summary, 0, &err)) return cli_report(&err);
    double t0 = cli_now();
    cli_json_begin(&d.json, d.summary.fp);
    cli_json_string(&d.json, "flintstone", fl_version());
    if (!step_check(&d) && !step_delaunay2(&d) && !step_reconstruct2(&d) && !step_delaunay3(&d))
        step_reconstruct3(&d);
    cli_json_double(&d.json, "seconds", cli_now() - t0);
    cli_json_end(&d.json);
    if (d.failed) {
        fl_out_abort(&d.summary);
        return d.failed;
    }
    if (fl_out_commit(&d.summary, &err)) return cli_report(&err);
    if (c.json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_string(&j, "summary", summary);
        cli_json_double(&j, "seconds", cli_now() - t0);
        cli_json_end(&j);
    } else if (!c.quiet) {
        printf("demo done in %.2f s; summary in %s\n", cli_now() - t0, summary);
    }
    return 0;
}

/* The 3D pipeline of demo/report: scattered points -> closed genus-0 boundary by constriction
 * (a mesh input starts here) -> topology and validity check -> distance to the surface the
 * points came from. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/pipeline.h"
#include "core/core.h"

typedef struct state3 {
    const char *name, *path;
    char mesh_path[1024]; /* where the mesh the later steps use is (input or reconstruction) */
    fl_mesh mesh;         /* owned */
    int have_mesh;
} state3;

static void step_reconstruct(pipeline *pl, state3 *s, fl_points *p)
{
    char out[1024], file[256], cmd[2300];
    snprintf(file, sizeof file, "%s-boundary.off", s->name);
    pl_path(pl, out, sizeof out, file);
    snprintf(cmd, sizeof cmd, "flintstone reconstruct %s -o %s", s->path, out);
    pl_step(pl, "reconstruct_3d", "Closed surface by constriction", NULL,
            "Constriction of the 3D Delaunay tetrahedralization (thesis §5.3): boundary "
            "tetrahedra are removed smallest γ-indicator first while the boundary stays a "
            "closed genus-0 2-manifold, until every point is on it.",
            cmd);
    fl_error err;
    fl_reconstruction3 rec = {0};
    fl_status st = fl_reconstruct3(p->coords, p->count, NULL, &rec, &err);
    fl_mesh m = {p->count, p->coords, rec.triangle_count, rec.tri};
    if (st == FL_OK) st = fl_write_mesh(out, &m, &err);
    if (st) {
        fl_reconstruction3_free(&rec);
        pl_step_failed(pl, "reconstruct 3d", &err);
        return;
    }
    pl_count(pl, "points", "points", rec.point_count, "input points");
    pl_count(pl, "delaunay_tetrahedra", "Delaunay tetrahedra", rec.delaunay_tet_count,
             "tetrahedra constriction started from");
    pl_count(pl, "removed", "removed tetrahedra", rec.removed_count, "by constriction");
    pl_count(pl, "faces", "boundary triangles", rec.triangle_count, "of the closed surface");
    pl_count(pl, "boundary_vertices", "boundary vertices", rec.boundary_vertex_count,
             "distinct points on the surface");
    pl_bool(pl, "all_on_boundary", "all points on the boundary", rec.all_on_boundary,
            rec.all_on_boundary ? "the surface passes through every distinct point"
                                : rec.reason);
    pl_num(pl, "volume", "volume", rec.volume, "units³", "enclosed by the surface");
    pl_text(pl, "output", "mesh file", file, "the boundary as OFF");
    char line[256];
    snprintf(line, sizeof line, "boundary: %zu of %zu points on %zu triangles",
             rec.boundary_vertex_count, rec.unique_count, rec.triangle_count);
    /* Later steps use the mesh: take the points and triangles over. */
    s->mesh.vertex_count = p->count;
    s->mesh.xyz = p->coords;
    p->coords = NULL;
    p->count = 0;
    s->mesh.triangle_count = rec.triangle_count;
    s->mesh.tri = rec.tri;
    rec.tri = NULL;
    s->have_mesh = 1;
    snprintf(s->mesh_path, sizeof s->mesh_path, "%s", out);
    fl_reconstruction3_free(&rec);
    pl_step_end(pl, line);
}

static void step_check(pipeline *pl, state3 *s)
{
    char cmd[2300];
    snprintf(cmd, sizeof cmd, "flintstone check %s", s->mesh_path);
    pl_step(pl, "check", "Topology and validity", NULL,
            "The mesh checked independently of how it was made: closed, manifold, oriented, "
            "genus per component, and self-intersections decided with exact predicates.",
            cmd);
    fl_error err;
    fl_mesh_report r = {0};
    if (fl_mesh_check(&s->mesh, NULL, &r, &err)) {
        pl_step_failed(pl, "check", &err);
        return;
    }
    pl_count(pl, "vertices", "vertices", r.vertices, "");
    pl_count(pl, "faces", "triangles", r.faces, "");
    pl_bool(pl, "closed", "closed", r.closed, "every edge has exactly two triangles");
    pl_bool(pl, "manifold", "manifold", r.manifold, "no non-manifold edge or vertex");
    pl_bool(pl, "oriented", "oriented", r.oriented, "neighbouring triangles agree");
    cli_json_int(pl->json, "genus", r.genus);
    char g[32];
    snprintf(g, sizeof g, "%lld", r.genus);
    cli_page_text(pl->page, "genus", g, "handles of the surface (-1: not a closed manifold)");
    pl_count(pl, "self_intersections", "self-intersections", r.self_intersections,
             "pairs of triangles that intersect (exact)");
    pl_num(pl, "area", "area", r.area, "units²", "");
    pl_num(pl, "volume", "volume", r.volume, "units³", "enclosed volume (divergence theorem)");
    char line[256];
    snprintf(line, sizeof line, "check: %s, genus %lld, %zu self-intersections",
             r.closed && r.manifold ? "closed manifold" : "NOT a closed manifold", r.genus,
             r.self_intersections);
    fl_mesh_report_free(&r);
    pl_step_end(pl, line);
}

/* Largest distance from the vertices of `from` to the surface `to` (exact at the vertices). */
static fl_status max_vertex_distance(const fl_mesh *to, const fl_mesh *from, double *out,
                                     fl_error *err)
{
    fl_sweep *sw;
    fl_status st = fl_sweep_build(to, NULL, &sw, err);
    if (st) return st;
    fl_closest *r = fl_alloc_array(from->vertex_count, sizeof *r);
    st = r ? fl_sweep_closest(sw, from->xyz, from->vertex_count, 0, r, err)
           : fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    *out = 0;
    for (size_t i = 0; st == FL_OK && i < from->vertex_count; i++)
        *out = fmax(*out, r[i].distance);
    free(r);
    fl_sweep_free(sw);
    return st;
}

static void step_distance(pipeline *pl, state3 *s, const char *truth)
{
    char cmd[2300];
    snprintf(cmd, sizeof cmd, "flintstone closest %s %s --json", truth, s->mesh_path);
    pl_step(pl, "distance_3d", "Distance to the original surface", NULL,
            "How far the surface is from the one the points were sampled on: the largest "
            "distance from the reference mesh's vertices to ours and from ours to it, by "
            "Meshsweeper closest-point queries.",
            cmd);
    fl_error err;
    fl_mesh t;
    if (fl_read_mesh(truth, &t, &err)) {
        pl_step_failed(pl, "reading the ground truth", &err);
        return;
    }
    double d_tr = 0, d_rt = 0;
    fl_status st = max_vertex_distance(&s->mesh, &t, &d_tr, &err);
    if (st == FL_OK) st = max_vertex_distance(&t, &s->mesh, &d_rt, &err);
    fl_mesh_free(&t);
    if (st) {
        pl_step_failed(pl, "distance", &err);
        return;
    }
    pl_num(pl, "truth_to_mesh", "reference → ours", d_tr, "units",
           "largest distance from a reference vertex to our surface");
    pl_num(pl, "mesh_to_truth", "ours → reference", d_rt, "units",
           "largest distance from our vertices to the reference surface");
    char line[256];
    snprintf(line, sizeof line, "distance to the true surface: %.4g", fmax(d_tr, d_rt));
    pl_step_end(pl, line);
}

void pl_run_3d(pipeline *pl, const char *name, const char *path, const char *truth)
{
    state3 s = {name, path, "", {0}, 0};
    char title[512], text[1400];
    fl_error err;
    fl_mesh in;
    int is_mesh = 0;
    if (fl_read_mesh(path, &in, &err) == FL_OK) {
        is_mesh = in.triangle_count > 0;
        if (is_mesh) {
            s.mesh = in;
            s.have_mesh = 1;
            snprintf(s.mesh_path, sizeof s.mesh_path, "%s", path);
        } else {
            fl_mesh_free(&in);
        }
    }
    snprintf(title, sizeof title, "%s: %s", name,
             is_mesh ? "a closed mesh" : "scattered 3D points to a closed surface");
    snprintf(text, sizeof text, "Input: %s.%s", path,
             truth ? " Ground truth for the distance check: the surface they were sampled on."
                   : "");
    pl_group_begin(pl, name, title, text);
    if (!is_mesh) {
        fl_points p = {0};
        fl_status st = fl_read_points(path, &p, &err);
        if (st == FL_OK && p.dim != 3)
            st = fl_fail(&err, FL_ERR_INPUT, path, -1, "expected 3D points, got %dD", p.dim);
        if (st) {
            pl_step(pl, "input", "Input", NULL, "Reading the points.", NULL);
            pl_step_failed(pl, "reading the input", &err);
        } else {
            step_reconstruct(pl, &s, &p);
        }
        fl_points_free(&p);
    }
    if (s.have_mesh) {
        step_check(pl, &s);
        if (truth) step_distance(pl, &s, truth);
    }
    pl_group_end(pl);
    if (s.have_mesh) fl_mesh_free(&s.mesh);
}

/* The 2D pipeline of demo/report: scattered points -> Delaunay -> boundary polygon by
 * constriction -> flintstone tree and its approximations -> point inclusion -> distance to the
 * curve the points came from. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/commands.h"
#include "cli/pipeline.h"
#include "core/core.h"

typedef struct state2 {
    const char *name, *path;
    fl_points pts;
    fl_polygon boundary; /* the reconstruction's polygon (one ring), or empty */
} state2;

static void step_delaunay(pipeline *pl, state2 *s)
{
    char out[1024], file[256], cmd[2300];
    snprintf(file, sizeof file, "%s-delaunay.svg", s->name);
    pl_path(pl, out, sizeof out, file);
    snprintf(cmd, sizeof cmd, "flintstone delaunay %s --verify -o %s", s->path, out);
    pl_step(pl, "delaunay_2d", "Delaunay triangulation", file,
            "The Delaunay triangulation of the points, γ([-1,1],[0,1]) in the thesis's terms "
            "(§3.3): constriction starts from it. Every triangle is checked with exact in-circle "
            "tests.",
            cmd);
    fl_error err;
    fl_dt2 dt = {0};
    fl_status st = fl_dt2_build(s->pts.coords, s->pts.count, NULL, &dt, &err);
    if (st == FL_OK) st = fl_dt2_verify(s->pts.coords, &dt, &err);
    if (st == FL_OK) st = cli_write_dt2(out, &s->pts, &dt, &err);
    if (st) {
        fl_dt2_free(&dt);
        pl_step_failed(pl, "delaunay 2d", &err);
        return;
    }
    pl_count(pl, "points", "points", dt.point_count, "input points");
    pl_count(pl, "triangles", "triangles", dt.triangle_count, "Delaunay triangles");
    pl_count(pl, "hull_edges", "hull edges", dt.hull_count, "edges of the convex hull");
    pl_bool(pl, "valid", "verified", 1, "every triangle passed the exact empty-circle test");
    char line[256];
    snprintf(line, sizeof line, "delaunay: %zu triangles, verified", dt.triangle_count);
    fl_dt2_free(&dt);
    pl_step_end(pl, line);
}

/* The boundary cycle as a one-ring polygon for the later steps. */
static fl_status boundary_polygon(const fl_points *p, const fl_reconstruction2 *rec,
                                  fl_polygon *poly, fl_error *err)
{
    memset(poly, 0, sizeof *poly);
    poly->xy = fl_alloc_array(rec->boundary_count, 2 * sizeof(double));
    poly->ring_start = malloc(2 * sizeof(size_t));
    poly->polygon_start = malloc(2 * sizeof(size_t));
    if (!poly->xy || !poly->ring_start || !poly->polygon_start) {
        fl_polygon_free(poly);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    for (size_t i = 0; i < rec->boundary_count; i++) {
        poly->xy[2 * i] = p->coords[2 * rec->boundary[i]];
        poly->xy[2 * i + 1] = p->coords[2 * rec->boundary[i] + 1];
    }
    poly->vertex_count = rec->boundary_count;
    poly->ring_count = 1;
    poly->ring_start[0] = 0;
    poly->ring_start[1] = rec->boundary_count;
    poly->polygon_count = 1;
    poly->polygon_start[0] = 0;
    poly->polygon_start[1] = 1;
    return FL_OK;
}

static void step_reconstruct(pipeline *pl, state2 *s)
{
    char out[1024], poly_out[1024], file[256], poly_file[256], cmd[2300];
    snprintf(file, sizeof file, "%s-boundary.svg", s->name);
    snprintf(poly_file, sizeof poly_file, "%s-boundary.xy", s->name);
    pl_path(pl, out, sizeof out, file);
    pl_path(pl, poly_out, sizeof poly_out, poly_file);
    snprintf(cmd, sizeof cmd, "flintstone reconstruct %s -o %s", s->path, out);
    pl_step(pl, "reconstruct_2d", "Boundary polygon by constriction", file,
            "Constriction (thesis Algorithm 5.1) deletes Delaunay triangles from the convex hull "
            "inward, smallest γ-indicator first, until every point lies on the boundary: a "
            "simple polygon through all points (bold), the Delaunay triangulation faint.",
            cmd);
    fl_error err;
    fl_reconstruction2 rec = {0};
    fl_status st = fl_reconstruct2(s->pts.coords, s->pts.count, NULL, &rec, &err);
    if (st == FL_OK) st = fl_write_reconstruction2(out, s->pts.coords, s->pts.count, &rec, &err);
    if (st == FL_OK)
        st = fl_write_reconstruction2(poly_out, s->pts.coords, s->pts.count, &rec, &err);
    if (st == FL_OK) st = boundary_polygon(&s->pts, &rec, &s->boundary, &err);
    if (st) {
        fl_reconstruction2_free(&rec);
        pl_step_failed(pl, "reconstruct 2d", &err);
        return;
    }
    pl_count(pl, "points", "points", rec.point_count, "input points");
    pl_count(pl, "boundary_vertices", "boundary vertices", rec.boundary_count,
             "vertices of the polygon");
    pl_bool(pl, "all_on_boundary", "all points on the boundary", rec.all_on_boundary,
            rec.all_on_boundary ? "the polygon passes through every distinct point"
                                : rec.reason);
    pl_num(pl, "augmented_c0", "augmentation c0", rec.augmented_c0, "",
           "c0 of γ([-1,1],[c0,1]) needed when constriction locked (§5.4); n/a: Delaunay "
           "sufficed");
    pl_num(pl, "area", "area", rec.area, "units²", "area enclosed by the polygon");
    pl_text(pl, "output", "polygon file", poly_file, "the boundary as an .xy ring");
    char line[256];
    snprintf(line, sizeof line, "boundary: %zu of %zu points on a simple polygon",
             rec.boundary_count, rec.unique_count);
    fl_reconstruction2_free(&rec);
    pl_step_end(pl, line);
}

/* Three approximation levels spread over the tree's depth: coarse, middle, fine. */
static void step_hal(pipeline *pl, state2 *s)
{
    char out[1024], file[256], cmd[2300], poly_path[1024], poly_file[256];
    snprintf(poly_file, sizeof poly_file, "%s-boundary.xy", s->name);
    pl_path(pl, poly_path, sizeof poly_path, poly_file);
    fl_error err;
    fl_hal2 hal;
    fl_status st = fl_hal2_build(&s->boundary, NULL, &hal, &err);
    uint32_t levels[3] = {2, 4, 6};
    if (st == FL_OK) {
        uint32_t d = hal.depth < 3 ? 3 : hal.depth;
        levels[0] = (d + 3) / 4;
        levels[1] = (d + 1) / 2;
        levels[2] = (3 * d + 2) / 4;
    }
    snprintf(file, sizeof file, "%s-hal-%u.svg", s->name, levels[1]);
    pl_path(pl, out, sizeof out, file);
    snprintf(cmd, sizeof cmd, "flintstone hal %s --level %u -o %s", poly_path, levels[1], out);
    pl_step(pl, "hal_2d", "Flintstones: hierarchical approximation", file,
            "The HAL tree (thesis §7.2): each polyline between two vertices is bounded by a "
            "flintstone of two discs; refining a level splits it at its extreme vertex. Each "
            "level is an approximating polygon with a certified distance bound.",
            cmd);
    if (st) {
        pl_step_failed(pl, "flintstone tree", &err);
        return;
    }
    pl_count(pl, "depth", "tree depth", hal.depth, "deepest level; it reproduces the polygon");
    pl_count(pl, "nodes", "flintstones", hal.node_count, "nodes of the tree");
    cli_json_open_array(pl->json, "levels");
    for (int k = 0; k < 3 && st == FL_OK; k++) {
        fl_polygon approx = {0};
        double error = 0;
        st = fl_hal2_approximate_level(&hal, levels[k], &approx, &error, &err);
        char lf[256], lp[1024];
        snprintf(lf, sizeof lf, "%s-hal-%u.svg", s->name, levels[k]);
        pl_path(pl, lp, sizeof lp, lf);
        if (st == FL_OK) st = fl_write_polygon(lp, &approx, &err);
        if (st == FL_OK) {
            cli_json_open_object(pl->json, NULL);
            cli_json_uint(pl->json, "level", levels[k]);
            cli_json_uint(pl->json, "edges", approx.vertex_count);
            cli_json_double(pl->json, "error", error);
            cli_json_close(pl->json);
            char name[64], meaning[128];
            snprintf(name, sizeof name, "level %u", levels[k]);
            snprintf(meaning, sizeof meaning,
                     "%zu edges; every boundary point within this distance of them",
                     approx.vertex_count);
            cli_page_number(pl->page, name, error, "units", meaning);
        }
        fl_polygon_free(&approx);
    }
    cli_json_close(pl->json);
    fl_hal2_free(&hal);
    if (st) {
        pl_step_failed(pl, "flintstone approximation", &err);
        return;
    }
    pl_step_end(pl, "flintstones: three approximation levels");
}

/* A grid of queries over the polygon's bounding box, answered through the tree. */
static void step_inside(pipeline *pl, state2 *s)
{
    enum { side = 200 };
    char cmd[2300], poly_file[256];
    snprintf(poly_file, sizeof poly_file, "%s/%s-boundary.xy", pl->out_dir, s->name);
    snprintf(cmd, sizeof cmd, "flintstone inside %s QUERIES.xy --json", poly_file);
    pl_step(pl, "inside_2d", "Point inclusion", NULL,
            "A 200 × 200 grid over the polygon's bounding box, each point classified inside, "
            "outside or on the boundary by the flintstone tree (exact orientation tests; HAL "
            "paper §5.1).",
            cmd);
    const fl_polygon *b = &s->boundary;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < b->vertex_count; i++)
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], b->xy[2 * i + k]);
            hi[k] = fmax(hi[k], b->xy[2 * i + k]);
        }
    fl_error err;
    fl_hal2 hal;
    double *q = fl_alloc_array(side * side, 2 * sizeof(double));
    uint8_t *where = malloc(side * side);
    fl_status st = q && where ? fl_hal2_build(b, NULL, &hal, &err)
                              : fl_fail(&err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    if (st) {
        free(q);
        free(where);
        pl_step_failed(pl, "point inclusion", &err);
        return;
    }
    for (int i = 0; i < side; i++)
        for (int j = 0; j < side; j++) {
            q[2 * (i * side + j)] = lo[0] + (hi[0] - lo[0]) * (j + 0.5) / side;
            q[2 * (i * side + j) + 1] = lo[1] + (hi[1] - lo[1]) * (i + 0.5) / side;
        }
    double t0 = cli_now();
    st = fl_hal2_contains(&hal, q, side * side, where, &err);
    double t = cli_now() - t0;
    size_t count[3] = {0, 0, 0};
    for (size_t i = 0; st == FL_OK && i < side * side; i++) count[where[i] % 3]++;
    fl_hal2_free(&hal);
    free(q);
    free(where);
    if (st) {
        pl_step_failed(pl, "point inclusion", &err);
        return;
    }
    pl_count(pl, "queries", "queries", side * side, "grid points classified");
    pl_count(pl, "inside", "inside", count[FL_HAL2_INSIDE], "strictly inside the polygon");
    pl_count(pl, "boundary", "on the boundary", count[FL_HAL2_BOUNDARY], "exactly on an edge");
    double area = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (double)count[FL_HAL2_INSIDE] / (side * side);
    pl_num(pl, "area_estimate", "area from the grid", area, "units²",
           "bounding-box area × fraction inside; compare with the polygon's exact area");
    pl_num(pl, "queries_per_second", "throughput", side * side / fmax(t, 1e-9), "queries/s",
           "classification rate through the tree");
    char line[256];
    snprintf(line, sizeof line, "inside: %zu of %d grid points inside", count[FL_HAL2_INSIDE],
             side * side);
    pl_step_end(pl, line);
}

/* Largest distance from samples of one curve to the other polyline: a lower bound on the
 * directed Hausdorff distance, exact at the samples (Meshsweeper queries). */
static fl_status max_distance(const double *to, size_t nto, const double *from, size_t nfrom,
                              double *out, size_t *at, fl_error *err)
{
    fl_sweep *sw;
    fl_status st = fl_sweep_polyline_build(to, nto, 2, 1, NULL, &sw, err);
    if (st) return st;
    fl_closest *r = fl_alloc_array(nfrom, sizeof *r);
    st = r ? fl_sweep_closest(sw, from, nfrom, 0, r, err)
           : fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    *out = 0;
    *at = 0;
    for (size_t i = 0; st == FL_OK && i < nfrom; i++)
        if (r[i].distance > *out) {
            *out = r[i].distance;
            *at = i;
        }
    free(r);
    fl_sweep_free(sw);
    return st;
}

static void step_distance(pipeline *pl, state2 *s, const char *truth)
{
    char cmd[2300];
    snprintf(cmd, sizeof cmd, "flintstone closest %s/%s-boundary.xy %s --json", pl->out_dir,
             s->name, truth);
    pl_step(pl, "distance_2d", "Distance to the original curve", NULL,
            "How far the reconstructed polygon is from the curve the points were sampled on: "
            "the largest distance from the curve's dense samples to the polygon and from the "
            "polygon's vertices to the curve, by Meshsweeper closest-point queries.",
            cmd);
    fl_error err;
    fl_points t;
    if (fl_read_points(truth, &t, &err)) {
        pl_step_failed(pl, "reading the ground truth", &err);
        return;
    }
    double d_tr = 0, d_rt = 0;
    size_t at_tr = 0, at_rt = 0;
    fl_status st = t.dim == 2 ? FL_OK
                              : fl_fail(&err, FL_ERR_INPUT, truth, -1, "expected a 2D polyline");
    const fl_polygon *b = &s->boundary;
    if (st == FL_OK)
        st = max_distance(b->xy, b->vertex_count, t.coords, t.count, &d_tr, &at_tr, &err);
    if (st == FL_OK)
        st = max_distance(t.coords, t.count, b->xy, b->vertex_count, &d_rt, &at_rt, &err);
    fl_points_free(&t);
    if (st) {
        pl_step_failed(pl, "distance", &err);
        return;
    }
    pl_num(pl, "truth_to_boundary", "curve → polygon", d_tr, "units",
           "largest distance from a curve sample to the polygon");
    pl_num(pl, "boundary_to_truth", "polygon → curve", d_rt, "units",
           "largest distance from a polygon vertex to the curve (≈ 0: they were sampled on it)");
    char line[256];
    snprintf(line, sizeof line, "distance to the true curve: %.4g", fmax(d_tr, d_rt));
    pl_step_end(pl, line);
}

void pl_run_2d(pipeline *pl, const char *name, const char *path, const char *truth)
{
    state2 s = {name, path, {0}, {0}};
    char title[512], text[1400];
    snprintf(title, sizeof title, "%s: scattered 2D points to a closed boundary", name);
    snprintf(text, sizeof text, "Input: %s.%s", path,
             truth ? " Ground truth for the distance check: the curve they were sampled on." : "");
    pl_group_begin(pl, name, title, text);
    fl_error err;
    fl_status st = fl_read_points(path, &s.pts, &err);
    if (st == FL_OK && s.pts.dim != 2)
        st = fl_fail(&err, FL_ERR_INPUT, path, -1, "expected 2D points, got %dD", s.pts.dim);
    if (st) {
        pl_step(pl, "input", "Input", NULL, "Reading the points.", NULL);
        pl_step_failed(pl, "reading the points", &err);
    } else {
        step_delaunay(pl, &s);
        step_reconstruct(pl, &s);
        if (s.boundary.vertex_count) {
            step_hal(pl, &s);
            step_inside(pl, &s);
            if (truth) step_distance(pl, &s, truth);
        }
    }
    pl_group_end(pl);
    fl_polygon_free(&s.boundary);
    fl_points_free(&s.pts);
}

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
    char file[256], cmd[2300], poly_path[1024], poly_file[256];
    snprintf(poly_file, sizeof poly_file, "%s-boundary.xy", s->name);
    pl_path(pl, poly_path, sizeof poly_path, poly_file);
    fl_error err;
    fl_hal2 hal;
    fl_status st = fl_hal2_build(&s->boundary, NULL, &hal, &err);
    uint32_t levels[3] = {2, 4, 6};
    if (st == FL_OK) {
        uint32_t d = hal.depth < 8 ? 8 : hal.depth;
        levels[0] = d / 8;
        levels[1] = d / 4;
        levels[2] = d / 2;
    }
    snprintf(file, sizeof file, "%s-hal-%u.svg", s->name, levels[1]);
    snprintf(cmd, sizeof cmd, "flintstone hal %s --level %u -o %s/%s-hal-%u.xy", poly_path,
             levels[1], pl->out_dir, s->name, levels[1]);
    pl_step(pl, "hal_2d", "Flintstones: hierarchical approximation", file,
            "The HAL tree (thesis §7.2): each polyline between two vertices is bounded by a "
            "flintstone of two discs; refining a level splits it at its extreme vertex. Each "
            "level is an approximating polygon with a certified distance bound. Picture: the "
            "middle level (blue) over the polygon (grey) and the flintstones (orange) that "
            "bound what it cuts off.",
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
        snprintf(lf, sizeof lf, "%s-hal-%u.xy", s->name, levels[k]);
        pl_path(pl, lp, sizeof lp, lf);
        if (st == FL_OK) st = fl_write_polygon(lp, &approx, &err);
        char pic[1024];
        pl_path(pl, pic, sizeof pic, file);
        if (st == FL_OK && k == 1)
            st = cli_write_hal2_svg(pic, &hal, &approx, 1, levels[k], 0, &err);
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

/* The polygon and a thinned grid of the classified queries. */
static fl_status inside_picture(const pipeline *pl, const fl_polygon *b, const double *q,
                                const uint8_t *where, int side, const char *file, fl_error *err)
{
    fl_svg *svg;
    fl_status st = fl_svg_new(900, &svg, err);
    if (st) return st;
    fl_vec pts[3];
    for (int k = 0; k < 3; k++) fl_vec_init(&pts[k], 2 * sizeof(double));
    for (int i = 2; i < side; i += 5)
        for (int j = 2; j < side; j += 5) {
            size_t at = (size_t)i * side + j;
            if (fl_vec_push(&pts[where[at] % 3], q + 2 * at, 1))
                st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
        }
    fl_svg_style poly = {"#1f4e79", "#eef3f8", 2, 0, 0};
    fl_svg_style style[3] = {{"#9e9e9e", "#9e9e9e", 0, 0, 2},
                             {"#1a9850", "#1a9850", 0, 0, 2.5},
                             {"#d73027", "#d73027", 0, 0, 3}};
    if (st == FL_OK) st = fl_svg_add_polygon(svg, b, &poly, err);
    for (int k = 0; k < 3 && st == FL_OK; k++)
        if (pts[k].count) st = fl_svg_add_points(svg, pts[k].data, pts[k].count, &style[k], err);
    char path[1024];
    pl_path(pl, path, sizeof path, file);
    if (st == FL_OK) st = fl_svg_write(svg, path, err);
    for (int k = 0; k < 3; k++) fl_vec_free(&pts[k]);
    fl_svg_free(svg);
    return st;
}

/* A grid of queries over the polygon's bounding box, answered through the tree. */
static void step_inside(pipeline *pl, state2 *s)
{
    enum { side = 200 };
    char cmd[2300], poly_file[256], file[256];
    snprintf(poly_file, sizeof poly_file, "%s/%s-boundary.xy", pl->out_dir, s->name);
    snprintf(file, sizeof file, "%s-inside.svg", s->name);
    snprintf(cmd, sizeof cmd, "flintstone inside %s QUERIES.xy --json", poly_file);
    pl_step(pl, "inside_2d", "Point inclusion", file,
            "A 200 × 200 grid over the polygon's bounding box, each point classified inside, "
            "outside or on the boundary by the flintstone tree (exact orientation tests; HAL "
            "paper §5.1). Picture: every 25th query, green inside, grey outside.",
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
    if (st == FL_OK) st = inside_picture(pl, b, q, where, side, file, &err);
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

/* Certified Hausdorff distance between two closed 2D polylines, recorded under `key`. */
static void hausdorff_numbers(pipeline *pl, const fl_hausdorff_result *r, const char *a,
                              const char *b)
{
    char name[128], meaning[256];
    snprintf(name, sizeof name, "h(%s → %s)", a, b);
    snprintf(meaning, sizeof meaning, "certified interval [%.6g, %.6g]: every point of the %s "
             "is within the upper bound of the %s", r->h_ab[0], r->h_ab[1], a, b);
    cli_page_number(pl->page, name, r->h_ab[1], "units", meaning);
    snprintf(name, sizeof name, "h(%s → %s)", b, a);
    snprintf(meaning, sizeof meaning, "certified interval [%.6g, %.6g]", r->h_ba[0],
             r->h_ba[1]);
    cli_page_number(pl->page, name, r->h_ba[1], "units", meaning);
    cli_json_open_array(pl->json, "h_ab");
    cli_json_double(pl->json, NULL, r->h_ab[0]);
    cli_json_double(pl->json, NULL, r->h_ab[1]);
    cli_json_close(pl->json);
    cli_json_open_array(pl->json, "h_ba");
    cli_json_double(pl->json, NULL, r->h_ba[0]);
    cli_json_double(pl->json, NULL, r->h_ba[1]);
    cli_json_close(pl->json);
    cli_json_open_array(pl->json, "hausdorff");
    cli_json_double(pl->json, NULL, r->hausdorff[0]);
    cli_json_double(pl->json, NULL, r->hausdorff[1]);
    cli_json_close(pl->json);
    pl_count(pl, "samples", "samples", r->samples, "points where distances were measured");
}

static void step_distance(pipeline *pl, state2 *s, const fl_points *t, const char *truth)
{
    char cmd[2300];
    snprintf(cmd, sizeof cmd, "flintstone hausdorff %s %s/%s-boundary.xy --closed --relative 1e-4 "
             "--json", truth, pl->out_dir, s->name);
    pl_step(pl, "hausdorff_2d", "Hausdorff distance to the original curve", NULL,
            "How far the reconstructed polygon is from the curve the points were sampled on, over "
            "every point of both (not only the vertices): the certified Hausdorff distance "
            "(Guéziec §6), refined until its interval is narrower than 1e-4 of the diagonal.",
            cmd);
    fl_error err;
    fl_hausdorff_result r;
    fl_hausdorff_options o = {0};
    o.relative = 1e-4;
    o.both_directions = 1;
    const fl_polygon *b = &s->boundary;
    if (fl_hausdorff_polylines(t->coords, t->count, 1, b->xy, b->vertex_count, 1, 2, &o, &r,
                               &err)) {
        pl_step_failed(pl, "Hausdorff distance", &err);
        return;
    }
    hausdorff_numbers(pl, &r, "curve", "polygon");
    char line[256];
    snprintf(line, sizeof line, "Hausdorff distance to the true curve: [%.4g, %.4g]",
             r.hausdorff[0], r.hausdorff[1]);
    fl_hausdorff_result_free(&r);
    pl_step_end(pl, line);
}

/* The polygon made tangent-continuous: closed cubic Bézier curves through its vertices (thesis
 * §9.2), and how much closer that brings it to the true curve. */
static void step_smooth(pipeline *pl, state2 *s, const fl_points *t)
{
    char file[256], path[1024], cmd[2300];
    snprintf(file, sizeof file, "%s-smooth.svg", s->name);
    pl_path(pl, path, sizeof path, file);
    snprintf(cmd, sizeof cmd, "flintstone smooth %s/%s-boundary.xy -o %s --json", pl->out_dir,
             s->name, path);
    pl_step(pl, "smooth_2d", "G¹ curve through the polygon", file,
            "Closed cubic Bézier curves through every vertex with tangents estimated by "
            "length weighting (thesis §9.2); where the G¹ orientation condition fails the "
            "tangent is repaired.",
            cmd);
    fl_error err;
    fl_g1_curve c = {0};
    fl_polygon sampled = {0};
    fl_hausdorff_result r = {0};
    fl_status st = fl_g1_curve_build(&s->boundary, NULL, &c, &err);
    if (st == FL_OK) st = fl_g1_curve_write_svg(path, &c, &err);
    if (st == FL_OK) st = fl_g1_curve_sample(&c, 16, &sampled, &err);
    fl_hausdorff_options o = {0};
    o.relative = 1e-4;
    o.both_directions = 1;
    if (st == FL_OK && t)
        st = fl_hausdorff_polylines(t->coords, t->count, 1, sampled.xy, sampled.vertex_count, 1,
                                    2, &o, &r, &err);
    if (st) {
        fl_g1_curve_free(&c);
        fl_polygon_free(&sampled);
        pl_step_failed(pl, "smooth curve", &err);
        return;
    }
    pl_count(pl, "segments", "Bézier segments", c.vertex_count, "one a polygon edge");
    pl_count(pl, "orientation_repairs", "orientation repairs", c.orientation_repairs,
             "tangents replaced because the G¹ orientation condition failed");
    if (t) {
        char meaning[200];
        snprintf(meaning, sizeof meaning, "certified Hausdorff distance between the smooth curve "
                 "(16 samples a segment) and the true curve: [%.6g, %.6g]", r.hausdorff[0],
                 r.hausdorff[1]);
        pl_num(pl, "hausdorff_to_truth", "distance to the true curve", r.hausdorff[1], "units",
               meaning);
    }
    char line[256];
    snprintf(line, sizeof line, "smooth curve: %zu Bézier segments", c.vertex_count);
    fl_hausdorff_result_free(&r);
    fl_polygon_free(&sampled);
    fl_g1_curve_free(&c);
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
        fl_points t = {0};
        int have_truth = 0;
        if (s.boundary.vertex_count && truth) {
            fl_status ts = fl_read_points(truth, &t, &err);
            if (ts == FL_OK && t.dim != 2)
                ts = fl_fail(&err, FL_ERR_INPUT, truth, -1, "expected a 2D polyline, got %dD",
                             t.dim);
            if (ts == FL_OK) {
                have_truth = 1;
            } else {
                pl_step(pl, "truth", "Ground truth", NULL, "Reading the reference curve.", NULL);
                pl_step_failed(pl, "reading the ground truth", &err);
            }
        }
        if (s.boundary.vertex_count) {
            step_hal(pl, &s);
            step_inside(pl, &s);
            if (have_truth) step_distance(pl, &s, &t, truth);
            step_smooth(pl, &s, have_truth ? &t : NULL);
        }
        fl_points_free(&t);
    }
    pl_group_end(pl);
    fl_polygon_free(&s.boundary);
    fl_points_free(&s.pts);
}

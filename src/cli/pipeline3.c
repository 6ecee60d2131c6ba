/* The 3D pipeline of demo/report: scattered points -> closed genus-0 boundary by constriction
 * (a mesh input starts here) -> topology and validity check -> distance to the surface the
 * points came from. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/pipeline.h"
#include "core/core.h"


/* The mesh shaded from the report's view, with its edges when `wire`. */
static fl_status picture_mesh(const pipeline *pl, const fl_mesh *m, int wire, const char *file,
                              fl_error *err)
{
    fl_render *scene = pl_scene();
    if (!scene) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a picture");
    fl_render_mesh_style style = {0};
    style.wireframe = wire;
    fl_status st = fl_render_add_mesh(scene, m, &style, err);
    if (st) {
        fl_render_free(scene);
        return st;
    }
    return pl_scene_write(pl, scene, file, err);
}

typedef struct state3 {
    const char *name, *path;
    char mesh_path[1024]; /* where the mesh the later steps use is (input or reconstruction) */
    fl_mesh mesh;         /* owned */
    int have_mesh;
    long long genus;      /* from the check step; -1 when not a closed oriented manifold */
} state3;

static void step_reconstruct(pipeline *pl, state3 *s, fl_points *p)
{
    char out[1024], file[256], cmd[2300], pic[256];
    snprintf(file, sizeof file, "%s-boundary.off", s->name);
    snprintf(pic, sizeof pic, "%s-boundary.png", s->name);
    pl_path(pl, out, sizeof out, file);
    snprintf(cmd, sizeof cmd, "flintstone reconstruct %s -o %s", s->path, out);
    pl_step(pl, "reconstruct_3d", "Closed surface by constriction", pic,
            "Constriction of the 3D Delaunay tetrahedralization (thesis §5.3): boundary "
            "tetrahedra are removed smallest γ-indicator first while the boundary stays a "
            "closed genus-0 2-manifold, until every point is on it.",
            cmd);
    fl_error err;
    fl_reconstruction3 rec = {0};
    fl_status st = fl_reconstruct3(p->coords, p->count, NULL, &rec, &err);
    fl_mesh m = {p->count, p->coords, rec.triangle_count, rec.tri};
    if (st == FL_OK) st = fl_write_mesh(out, &m, &err);
    if (st == FL_OK) st = picture_mesh(pl, &m, 1, pic, &err);
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

static void step_check(pipeline *pl, state3 *s, int picture)
{
    char cmd[2300], pic[256];
    snprintf(cmd, sizeof cmd, "flintstone check %s", s->mesh_path);
    snprintf(pic, sizeof pic, "%s-mesh.png", s->name);
    pl_step(pl, "check", "Topology and validity", picture ? pic : NULL,
            "The mesh checked independently of how it was made: closed, manifold, oriented, "
            "genus per component, and self-intersections decided with exact predicates.",
            cmd);
    fl_error err;
    fl_mesh_report r = {0};
    if (fl_mesh_check(&s->mesh, NULL, &r, &err) ||
        (picture && picture_mesh(pl, &s->mesh, 1, pic, &err))) {
        fl_mesh_report_free(&r);
        pl_step_failed(pl, "check", &err);
        return;
    }
    s->genus = r.genus;
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

/* Three levels of the 3D flintstone tree (thesis §7.3, HAL paper §4) with their certified
 * errors; the middle one pictured. Needs a sphere-like surface. */
static void step_hal(pipeline *pl, state3 *s)
{
    char pic[256], cmd[2300];
    if (s->genus != 0) {
        pl_step_skipped(pl, "hal_3d", "Flintstones in 3D",
                        "The HAL tree needs a closed genus-0 surface; this one is not.");
        return;
    }
    fl_error err;
    fl_hal3 hal;
    fl_status st = fl_hal3_build(&s->mesh, NULL, &hal, &err);
    uint32_t levels[3] = {1, 2, 3};
    if (st == FL_OK) {
        uint32_t d = hal.depth < 8 ? 8 : hal.depth;
        levels[0] = d / 4;
        levels[1] = d / 2;
        levels[2] = 3 * d / 4;
    }
    snprintf(pic, sizeof pic, "%s-hal-%u.png", s->name, levels[1]);
    snprintf(cmd, sizeof cmd, "flintstone hal %s --level %u -o %s/%s-hal-%u.off", s->mesh_path,
             levels[1], pl->out_dir, s->name, levels[1]);
    pl_step(pl, "hal_3d", "Flintstones in 3D: hierarchical approximation", pic,
            "The HAL tree of the surface (thesis §7.3): three vertices on the smallest ball "
            "containing all make level 0; each level splits triangles at the vertex that is "
            "extreme for its part of the surface, bounded by a flintstone of two balls. Picture: "
            "the middle level.",
            cmd);
    if (st) {
        pl_step_failed(pl, "3D flintstone tree", &err);
        return;
    }
    pl_count(pl, "depth", "tree depth", hal.depth, "deepest level; it reproduces the mesh");
    pl_count(pl, "nodes", "flintstones", hal.node_count, "nodes of the tree");
    cli_json_open_array(pl->json, "levels");
    for (int k = 0; k < 3 && st == FL_OK; k++) {
        fl_mesh approx = {0};
        double error = 0;
        st = fl_hal3_approximate_level(&hal, levels[k], &approx, &error, &err);
        if (st == FL_OK && k == 1) st = picture_mesh(pl, &approx, 1, pic, &err);
        if (st == FL_OK) {
            cli_json_open_object(pl->json, NULL);
            cli_json_uint(pl->json, "level", levels[k]);
            cli_json_uint(pl->json, "faces", approx.triangle_count);
            cli_json_double(pl->json, "error", error);
            cli_json_close(pl->json);
            char name[64], meaning[160];
            snprintf(name, sizeof name, "level %u", levels[k]);
            snprintf(meaning, sizeof meaning,
                     "%zu triangles; every point of the surface within this distance of them",
                     approx.triangle_count);
            cli_page_number(pl->page, name, error, "units", meaning);
        }
        fl_mesh_free(&approx);
    }
    cli_json_close(pl->json);
    fl_hal3_free(&hal);
    if (st) {
        pl_step_failed(pl, "3D flintstone approximation", &err);
        return;
    }
    pl_step_end(pl, "flintstones: three approximation levels");
}

static void json_interval(cli_json *j, const char *key, const double v[2])
{
    cli_json_open_array(j, key);
    cli_json_double(j, NULL, v[0]);
    cli_json_double(j, NULL, v[1]);
    cli_json_close(j);
}

/* Certified Hausdorff distance to the reference surface, and the distance field over ours. */
static void step_distance(pipeline *pl, state3 *s, const char *truth)
{
    char cmd[2300], pic[256];
    snprintf(pic, sizeof pic, "%s-distance.png", s->name);
    snprintf(cmd, sizeof cmd, "flintstone hausdorff %s %s --relative 1e-3 --json", truth,
             s->mesh_path);
    pl_step(pl, "hausdorff_3d", "Hausdorff distance to the original surface", pic,
            "How far the surface is from the one the points were sampled on, over every point of "
            "both: the certified Hausdorff distance (Guéziec §6), to 1e-3 of the diagonal. "
            "Picture: our surface coloured by its distance to the reference, blue 0 to red the "
            "largest.",
            cmd);
    fl_error err;
    fl_mesh t;
    if (fl_read_mesh(truth, &t, &err)) {
        pl_step_failed(pl, "reading the ground truth", &err);
        return;
    }
    fl_hausdorff_options o = {0};
    o.relative = 1e-3;
    o.both_directions = 1;
    o.keep_field = 1;
    fl_hausdorff_result r = {0};
    fl_status st = fl_hausdorff_meshes(&t, &s->mesh, &o, &r, &err);
    if (st == FL_OK) {
        const fl_hausdorff_field *f = &r.field_ba; /* samples of ours, distances to the truth */
        fl_render *scene = pl_scene();
        fl_render_mesh_style style = {0};
        style.scalars = f->distance;
        style.scalar_min = 0;
        style.scalar_max = r.hausdorff[1];
        st = scene ? fl_render_add_mesh(scene, &f->mesh, &style, &err)
                   : fl_fail(&err, FL_ERR_NOMEM, NULL, -1, "out of memory for a picture");
        if (st == FL_OK)
            st = pl_scene_write(pl, scene, pic, &err);
        else
            fl_render_free(scene);
    }
    fl_mesh_free(&t);
    if (st) {
        fl_hausdorff_result_free(&r);
        pl_step_failed(pl, "Hausdorff distance", &err);
        return;
    }
    char meaning[200];
    snprintf(meaning, sizeof meaning, "certified interval [%.6g, %.6g]: every point of the "
             "reference is within the upper bound of ours", r.h_ab[0], r.h_ab[1]);
    cli_page_number(pl->page, "h(reference → ours)", r.h_ab[1], "units", meaning);
    snprintf(meaning, sizeof meaning, "certified interval [%.6g, %.6g]", r.h_ba[0], r.h_ba[1]);
    cli_page_number(pl->page, "h(ours → reference)", r.h_ba[1], "units", meaning);
    json_interval(pl->json, "h_ab", r.h_ab);
    json_interval(pl->json, "h_ba", r.h_ba);
    json_interval(pl->json, "hausdorff", r.hausdorff);
    pl_count(pl, "samples", "samples", r.samples, "points where distances were measured");
    char line[256];
    snprintf(line, sizeof line, "Hausdorff distance to the true surface: [%.4g, %.4g]",
             r.hausdorff[0], r.hausdorff[1]);
    fl_hausdorff_result_free(&r);
    pl_step_end(pl, line);
}

/* The G1 surface of cubic Bézier triangles through the mesh (three-split, thesis §9.6),
 * pictured with reflection lines, which make tangent continuity visible. */
static void step_smooth(pipeline *pl, state3 *s)
{
    char pic[256], cmd[2300];
    snprintf(pic, sizeof pic, "%s-smooth.png", s->name);
    snprintf(cmd, sizeof cmd, "flintstone smooth %s --tess 4 -o %s/%s-smooth.off --json",
             s->mesh_path, pl->out_dir, s->name);
    pl_step(pl, "smooth_3d", "G¹ surface of cubic Bézier triangles", pic,
            "Cubic Bézier triangles, three per mesh triangle (three-split, thesis §9.6), "
            "interpolating the vertices and area-weighted normals; tangent-plane continuity is "
            "measured along every edge. Picture: reflection lines (zebra), which bend without "
            "kinks on a G¹ surface.",
            cmd);
    fl_error err;
    fl_g1_surface g = {0};
    fl_g1_metrics m = {0};
    fl_mesh tess = {0};
    double *normals = NULL;
    char out[1024], file[256];
    snprintf(file, sizeof file, "%s-smooth.off", s->name);
    pl_path(pl, out, sizeof out, file);
    fl_status st = fl_g1_surface_build(&s->mesh, NULL, &g, &err);
    if (st == FL_OK) st = fl_g1_surface_measure(&g, &s->mesh, 8, &m, &err);
    if (st == FL_OK) st = fl_g1_surface_tessellate(&g, 4, &tess, &normals, &err);
    if (st == FL_OK) st = fl_write_mesh(out, &tess, &err);
    if (st == FL_OK) {
        fl_render *scene = pl_scene();
        fl_render_mesh_style style = {0};
        style.normals = normals;
        style.zebra = 1;
        st = scene ? fl_render_add_mesh(scene, &tess, &style, &err)
                   : fl_fail(&err, FL_ERR_NOMEM, NULL, -1, "out of memory for a picture");
        if (st == FL_OK)
            st = pl_scene_write(pl, scene, pic, &err);
        else
            fl_render_free(scene);
    }
    free(normals);
    fl_mesh_free(&tess);
    if (st) {
        fl_g1_surface_free(&g);
        pl_step_failed(pl, "smooth surface", &err);
        return;
    }
    pl_count(pl, "patches", "Bézier patches", g.patch_count, "cubic triangles, three a face");
    pl_num(pl, "max_vertex_error", "vertex error", m.max_vertex_error, "units",
           "largest distance between a patch corner and its mesh vertex (interpolation)");
    pl_num(pl, "max_edge_normal_jump_deg", "normal jump across edges", m.max_edge_normal_jump_deg,
           "degrees", "largest angle between neighbouring patches' normals along their edges");
    pl_count(pl, "orientation_repairs", "orientation repairs", g.orientation_repairs,
             "vertex normals changed so the G¹ orientation condition holds");
    pl_num(pl, "max_deviation", "deviation from the mesh", m.max_deviation, "edge lengths",
           "largest distance of the surface from the mesh, in mean edge lengths");
    pl_text(pl, "output", "tessellation", file, "4 segments a patch edge, watertight");
    char line[256];
    snprintf(line, sizeof line, "smooth surface: %zu patches, normal jump %.2g degrees",
             g.patch_count, m.max_edge_normal_jump_deg);
    fl_g1_surface_free(&g);
    pl_step_end(pl, line);
}

void pl_run_3d(pipeline *pl, const char *name, const char *path, const char *truth)
{
    state3 s = {name, path, "", {0}, 0, -1};
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
        step_check(pl, &s, is_mesh);
        step_hal(pl, &s);
        if (truth) step_distance(pl, &s, truth);
        step_smooth(pl, &s);
        pl_step_skipped(pl, "skin", "Union of balls and skin surface",
                        "Approximating a polyhedron by a union of balls within ε (Cheng & Tan) "
                        "is not implemented yet; `flintstone skin --balls` meshes the skin of a "
                        "given ball set.");
    }
    pl_group_end(pl);
    if (s.have_mesh) fl_mesh_free(&s.mesh);
}

/* flintstone check FILE [--json] [--no-self-intersections]
 * Topology, validity and measures of a triangle mesh (.off .obj .ply .stl) or of planar
 * polygons (.xy .geojson). */
#include <math.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

static const char *usage_text =
    "usage: flintstone check FILE [--json] [--no-self-intersections] [--quiet]\n"
    "\n"
    "Reports what a mesh or polygon file is: for a triangle mesh (.off .obj .ply .stl) the\n"
    "counts, closed / manifold / oriented, Euler characteristic and genus per component,\n"
    "degenerate faces, duplicate vertices, self-intersecting triangle pairs (exact), bounding\n"
    "box, area and enclosed volume; for polygons (.xy .geojson) whether they are simple, their\n"
    "orientation, area and holes.\n"
    "\n"
    "  --no-self-intersections  skip the self-intersection search (the slowest check)\n"
    "  --json                   print one JSON object with every figure\n"
    "\n"
    "example: flintstone check data/demo/torus.off --json\n";

static int is_polygon_file(const char *path)
{
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    return strcmp(ext, "xy") == 0 || strcmp(ext, "geojson") == 0 || strcmp(ext, "json") == 0;
}

static void mesh_json(const fl_mesh_report *r, double seconds)
{
    cli_json j;
    cli_json_begin(&j, stdout);
    cli_json_string(&j, "kind", "mesh");
    cli_json_uint(&j, "vertices", r->vertices);
    cli_json_uint(&j, "faces", r->faces);
    cli_json_uint(&j, "edges", r->edges);
    cli_json_uint(&j, "components", r->components);
    cli_json_bool(&j, "closed", r->closed);
    cli_json_bool(&j, "manifold", r->manifold);
    cli_json_bool(&j, "oriented", r->oriented);
    cli_json_int(&j, "euler", r->euler);
    if (r->genus >= 0)
        cli_json_int(&j, "genus", r->genus);
    else
        cli_json_null(&j, "genus");
    cli_json_open_array(&j, "component_genus");
    for (size_t i = 0; i < r->components; i++) {
        if (r->component_genus[i] >= 0)
            cli_json_int(&j, NULL, r->component_genus[i]);
        else
            cli_json_null(&j, NULL);
    }
    cli_json_close(&j);
    cli_json_uint(&j, "boundary_edges", r->boundary_edges);
    cli_json_uint(&j, "nonmanifold_edges", r->nonmanifold_edges);
    cli_json_uint(&j, "nonmanifold_vertices", r->nonmanifold_vertices);
    cli_json_uint(&j, "misoriented_edges", r->misoriented_edges);
    cli_json_uint(&j, "unreferenced_vertices", r->unreferenced_vertices);
    cli_json_uint(&j, "degenerate_faces", r->degenerate_faces);
    cli_json_uint(&j, "duplicate_vertices", r->duplicate_vertices);
    if (r->self_intersections_checked)
        cli_json_uint(&j, "self_intersections", r->self_intersections);
    else
        cli_json_null(&j, "self_intersections");
    cli_json_open_array(&j, "bbox");
    for (int i = 0; i < 6; i++)
        cli_json_double(&j, NULL, r->bbox[i]);
    cli_json_close(&j);
    cli_json_double(&j, "area", r->area);
    if (isnan(r->volume))
        cli_json_null(&j, "volume");
    else
        cli_json_double(&j, "volume", r->volume);
    cli_json_double(&j, "seconds", seconds);
    cli_json_end(&j);
}

static void mesh_human(const char *path, const fl_mesh_report *r)
{
    printf("%s: %zu vertices, %zu faces, %zu edges, %zu component%s\n", path, r->vertices, r->faces,
           r->edges, r->components, r->components == 1 ? "" : "s");
    printf("  %s, %s, %s; Euler characteristic %lld", r->closed ? "closed" : "open",
           r->manifold ? "manifold" : "NOT manifold", r->oriented ? "oriented" : "NOT oriented",
           r->euler);
    if (r->genus >= 0) printf(", genus %lld", r->genus);
    printf("\n  degenerate faces %zu, duplicate vertices %zu, self-intersecting pairs ",
           r->degenerate_faces, r->duplicate_vertices);
    if (r->self_intersections_checked)
        printf("%zu\n", r->self_intersections);
    else
        printf("not checked\n");
    if (r->duplicate_vertices && r->self_intersections)
        printf("  note: vertices at equal positions are distinct vertices here, so triangles of\n"
               "  an unwelded triangle soup touch and count as intersecting\n");
    printf("  area %.6g", r->area);
    if (!isnan(r->volume)) printf(", volume %.6g", r->volume);
    printf("\n");
}

static int check_mesh(const char *path, const cli_common *c, int skip_si)
{
    fl_error err;
    fl_mesh mesh;
    double t0 = cli_now();
    if (fl_read_mesh(path, &mesh, &err)) return cli_report(&err);
    cli_progress prog;
    cli_progress_init(&prog, c);
    fl_mesh_check_options opt = {
        .skip_self_intersections = skip_si, .progress = cli_progress_fn, .progress_user = &prog};
    fl_mesh_report r;
    fl_status st = fl_mesh_check(&mesh, &opt, &r, &err);
    cli_progress_done(&prog);
    fl_mesh_free(&mesh);
    if (st) return cli_report(&err);
    if (c->json)
        mesh_json(&r, cli_now() - t0);
    else
        mesh_human(path, &r);
    fl_mesh_report_free(&r);
    return 0;
}

static const char *orientation_name(int o)
{
    return o > 0 ? "ccw" : o < 0 ? "cw" : "mixed";
}

static int check_polygon(const char *path, const cli_common *c)
{
    fl_error err;
    fl_polygon poly;
    double t0 = cli_now();
    if (fl_read_polygon(path, &poly, &err)) return cli_report(&err);
    fl_polygon_report r;
    fl_status st = fl_polygon_check(&poly, &r, &err);
    fl_polygon_free(&poly);
    if (st) return cli_report(&err);
    if (c->json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_string(&j, "kind", "polygon");
        cli_json_uint(&j, "vertices", r.vertices);
        cli_json_uint(&j, "rings", r.rings);
        cli_json_uint(&j, "polygons", r.polygons);
        cli_json_uint(&j, "holes", r.holes);
        cli_json_bool(&j, "simple", r.simple);
        cli_json_uint(&j, "edge_intersections", r.edge_intersections);
        cli_json_string(&j, "orientation", orientation_name(r.orientation));
        cli_json_double(&j, "area", r.area);
        if (r.holes_inside >= 0)
            cli_json_bool(&j, "holes_inside", r.holes_inside);
        else
            cli_json_null(&j, "holes_inside");
        cli_json_double(&j, "seconds", cli_now() - t0);
        cli_json_end(&j);
    } else {
        printf("%s: %zu polygon%s, %zu ring%s (%zu hole%s), %zu vertices\n", path, r.polygons,
               r.polygons == 1 ? "" : "s", r.rings, r.rings == 1 ? "" : "s", r.holes,
               r.holes == 1 ? "" : "s", r.vertices);
        printf("  %s (%zu crossing edge pairs), orientation %s, area %.6g\n",
               r.simple ? "simple" : "NOT simple", r.edge_intersections,
               orientation_name(r.orientation), r.area);
    }
    fl_polygon_report_free(&r);
    return 0;
}

int cmd_check(int argc, char **argv)
{
    cli_common c = {0};
    const char *input = NULL;
    int skip_si = 0;
    for (int i = 1; i < argc; i++) {
        int k = cli_common_option(&c, argc, argv, &i);
        if (k < 0) return 1;
        if (k > 0) continue;
        if (strcmp(argv[i], "--no-self-intersections") == 0)
            skip_si = 1;
        else if (argv[i][0] == '-' && argv[i][1])
            return cli_fail(1, "check: unknown option '%s' (see flintstone check --help)", argv[i]);
        else if (input)
            return cli_fail(1, "check: one input file, got '%s' and '%s'", input, argv[i]);
        else
            input = argv[i];
    }
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    if (!input) return cli_fail(1, "check: no input file (see flintstone check --help)");
    if (c.output) return cli_fail(1, "check: writes no file; -o is not used");
    return is_polygon_file(input) ? check_polygon(input, &c) : check_mesh(input, &c, skip_si);
}

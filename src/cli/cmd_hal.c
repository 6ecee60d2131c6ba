/* The flintstone (HAL) tree commands (thesis ch. 7, HAL paper §3-§5), on polygons (2D) or on
 * closed genus-0 triangle meshes (3D, chosen by the input's extension .off .obj .ply .stl):
 *   flintstone hal INPUT (--level L | --error E) [-o OUT]       approximation with certified error
 *   flintstone inside INPUT QUERIES [-o OUT.csv]                hierarchical point inclusion
 *   flintstone intersect A B [--first]                          hierarchical intersection */
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

static const char *hal_usage =
    "usage: flintstone hal POLYGON (--level L | --error E) [-o OUT] [--json] [--quiet]\n"
    "       flintstone hal MESH (--level L | --error E) [-o OUT.off] [--json] [--quiet]\n"
    "\n"
    "A MESH (.off .obj .ply .stl; closed, manifold, genus 0) gets the 3D flintstone tree\n"
    "(thesis §7.3) and an approximating closed mesh; --json then has faces, levels,\n"
    "approx_faces, error, seconds.\n"
    "\n"
    "Builds the flintstone tree of a polygon (.xy .geojson; holes are separate boundaries) and\n"
    "writes an approximating polygon: the approximation of level L (0 is the coarsest: two\n"
    "vertices a ring), or the adaptive one refined only where a node's certified width error\n"
    "(thesis Def. 7.4) exceeds E. The reported error is a certified bound on the distance of\n"
    "every original vertex from the approximation.\n"
    "\n"
    "  -o OUT   .xy .geojson .svg (the approximating polygon)\n"
    "  --json   vertices, levels, approx_vertices, error, seconds\n"
    "\n"
    "example: flintstone hal country.geojson --error 0.01 -o simple.geojson --json\n";

static const char *inside_usage =
    "usage: flintstone inside POLYGON QUERIES [-o OUT.csv] [--json] [--quiet]\n"
    "       flintstone inside MESH QUERIES [-o OUT.csv] [--json] [--quiet]\n"
    "\n"
    "With a MESH the queries are 3D points and the CSV rows are x,y,z,where.\n"
    "\n"
    "Classifies each query point (a 2D point file) against the polygon through its flintstone\n"
    "tree: inside, outside, or on the boundary (decided exactly). The CSV has one row a query:\n"
    "x,y,where.\n"
    "\n"
    "example: flintstone inside country.geojson points.xy -o where.csv --json\n";

static const char *intersect_usage =
    "usage: flintstone intersect A B [--first] [--json] [--quiet]\n"
    "\n"
    "A and B are both polygons or both meshes (then triangle pairs are counted).\n"
    "\n"
    "Do the boundaries of polygons A and B intersect (edges touching count)? Descends both\n"
    "flintstone trees together; --first stops at the first intersecting edge pair, otherwise\n"
    "every pair is counted.\n"
    "\n"
    "example: flintstone intersect a.geojson b.geojson --json\n";

/* 1 when the path names a triangle mesh (the 3D commands), by extension. */
static int is_mesh_path(const char *path)
{
    const char *dot = strrchr(path, '.');
    if (!dot) return 0;
    static const char *ext[] = {".off", ".obj", ".ply", ".stl", ".OFF", ".OBJ", ".PLY", ".STL"};
    for (size_t i = 0; i < sizeof ext / sizeof ext[0]; i++)
        if (!strcmp(dot, ext[i])) return 1;
    return 0;
}

/* Reads a mesh file and builds its 3D tree; prints the error and returns its exit code. */
static int load_hal3(const char *path, fl_hal3 *hal)
{
    fl_error err;
    fl_mesh mesh;
    if (fl_read_mesh(path, &mesh, &err)) return cli_report(&err);
    fl_status st = fl_hal3_build(&mesh, NULL, hal, &err);
    if (st) snprintf(err.file, sizeof err.file, "%s", path);
    fl_mesh_free(&mesh);
    return st ? cli_report(&err) : 0;
}

static int hal3_command(const char *input, const char *level_s, size_t level, double max_error,
                        const cli_common *c)
{
    double t0 = cli_now();
    fl_hal3 hal;
    int code = load_hal3(input, &hal);
    if (code) return code;
    fl_error err;
    fl_mesh approx = {0};
    double error = 0;
    uint32_t used_level = (uint32_t)level;
    fl_status st =
        level_s ? fl_hal3_approximate_level(&hal, (uint32_t)level, &approx, &error, &err)
                : fl_hal3_approximate_error(&hal, max_error, &approx, &error, &used_level, &err);
    if (st == FL_OK && c->output) st = fl_write_mesh(c->output, &approx, &err);
    if (st == FL_OK && c->json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_uint(&j, "faces", hal.mesh.triangle_count);
        cli_json_uint(&j, "levels", hal.depth);
        cli_json_uint(&j, "approx_faces", approx.triangle_count);
        cli_json_double(&j, "error", error);
        cli_json_double(&j, "seconds", cli_now() - t0);
        cli_json_end(&j);
    } else if (st == FL_OK && !c->quiet) {
        printf("%zu triangles, tree depth %u: approximation with %zu triangles, certified error "
               "%.6g\n",
               hal.mesh.triangle_count, hal.depth, approx.triangle_count, error);
    }
    fl_mesh_free(&approx);
    fl_hal3_free(&hal);
    return st ? cli_report(&err) : 0;
}

/* Reads a polygon file and builds its tree; prints the error and returns its exit code. */
static int load_hal(const char *path, fl_hal2 *hal)
{
    fl_error err;
    fl_polygon poly;
    if (fl_read_polygon(path, &poly, &err)) return cli_report(&err);
    fl_status st = fl_hal2_build(&poly, NULL, hal, &err);
    fl_polygon_free(&poly);
    return st ? cli_report(&err) : 0;
}

/* Collects positional arguments and the common options; `flags` lists extra boolean flags. */
static int parse_positional(int argc, char **argv, cli_common *c, const char **pos, int npos,
                            const char *flag, int *flag_set, const char *cmd)
{
    int k = 0;
    for (int i = 1; i < argc; i++) {
        int r = cli_common_option(c, argc, argv, &i);
        if (r < 0) return 1;
        if (r > 0) continue;
        if (flag && !strcmp(argv[i], flag))
            *flag_set = 1;
        else if (argv[i][0] == '-' && argv[i][1])
            return cli_fail(1, "%s: unknown option '%s' (see --help)", cmd, argv[i]);
        else if (k < npos)
            pos[k++] = argv[i];
        else
            return cli_fail(1, "%s: too many arguments ('%s')", cmd, argv[i]);
    }
    if (!c->help && k < npos) return cli_fail(1, "%s: missing input file (see --help)", cmd);
    return 0;
}

int cmd_hal(int argc, char **argv)
{
    cli_common c = {0};
    const char *input = NULL, *level_s = NULL, *error_s = NULL;
    for (int i = 1; i < argc; i++) {
        int r = cli_common_option(&c, argc, argv, &i);
        if (r < 0) return 1;
        if (r > 0) continue;
        int is_level = !strcmp(argv[i], "--level"), is_error = !strcmp(argv[i], "--error");
        if ((is_level || is_error) && i + 1 >= argc)
            return cli_fail(1, "hal: %s needs a value", argv[i]);
        if (is_level)
            level_s = argv[++i];
        else if (is_error)
            error_s = argv[++i];
        else if (argv[i][0] == '-' && argv[i][1])
            return cli_fail(1, "hal: unknown option '%s' (see --help)", argv[i]);
        else if (input)
            return cli_fail(1, "hal: one input file, got '%s' and '%s'", input, argv[i]);
        else
            input = argv[i];
    }
    if (c.help) {
        fputs(hal_usage, stdout);
        return 0;
    }
    if (!input) return cli_fail(1, "hal: no input file (see --help)");
    if ((level_s != NULL) == (error_s != NULL))
        return cli_fail(1, "hal: give exactly one of --level L and --error E");
    size_t level = 0;
    double max_error = 0;
    if (level_s && (cli_parse_size(level_s, &level) || level > UINT32_MAX))
        return cli_fail(1, "hal: --level takes a whole number >= 0, got '%s'", level_s);
    if (error_s && (cli_parse_double(error_s, &max_error) || max_error < 0))
        return cli_fail(1, "hal: --error takes a number >= 0, got '%s'", error_s);

    int code = cli_check_output(c.output, is_mesh_path(input) ? "off obj ply stl"
                                                              : "xy geojson json svg");
    if (code) return code;
    if (is_mesh_path(input)) return hal3_command(input, level_s, level, max_error, &c);
    double t0 = cli_now();
    fl_hal2 hal;
    code = load_hal(input, &hal);
    if (code) return code;
    fl_error err;
    fl_polygon approx = {0};
    double error = 0;
    uint32_t used_level = (uint32_t)level;
    fl_status st =
        level_s ? fl_hal2_approximate_level(&hal, (uint32_t)level, &approx, &error, &err)
                : fl_hal2_approximate_error(&hal, max_error, &approx, &error, &used_level, &err);
    char ext[16];
    fl_path_extension(c.output ? c.output : "", ext, sizeof ext);
    if (st == FL_OK && c.output && !strcmp(ext, "svg")) /* with the flintstones */
        st = cli_write_hal2_svg(c.output, &hal, &approx, level_s != NULL, (uint32_t)level,
                                max_error, &err);
    else if (st == FL_OK && c.output)
        st = fl_write_polygon(c.output, &approx, &err);
    if (st == FL_OK && c.json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_uint(&j, "vertices", hal.polygon.vertex_count);
        cli_json_uint(&j, "levels", hal.depth);
        cli_json_uint(&j, "approx_vertices", approx.vertex_count);
        cli_json_double(&j, "error", error);
        cli_json_double(&j, "seconds", cli_now() - t0);
        cli_json_end(&j);
    } else if (st == FL_OK && !c.quiet) {
        printf("%zu vertices, tree depth %u: approximation with %zu vertices, certified error "
               "%.6g\n",
               hal.polygon.vertex_count, hal.depth, approx.vertex_count, error);
    }
    fl_polygon_free(&approx);
    fl_hal2_free(&hal);
    return st ? cli_report(&err) : 0;
}

static const char *where_name(uint8_t w)
{
    return w == FL_HAL2_INSIDE ? "inside" : w == FL_HAL2_BOUNDARY ? "boundary" : "outside";
}

static fl_status write_where_csv3(const char *path, const fl_points *q, const uint8_t *where,
                                  fl_error *err)
{
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st) return st;
    fputs("x,y,z,where\n", out.fp);
    for (size_t i = 0; i < q->count; i++)
        fprintf(out.fp, "%.17g,%.17g,%.17g,%s\n", q->coords[3 * i], q->coords[3 * i + 1],
                q->coords[3 * i + 2], where_name(where[i]));
    return fl_out_commit(&out, err);
}

static int inside3(const char *mesh_path, const fl_points *q, const cli_common *c, double t0)
{
    if (q->dim != 3) return cli_fail(2, "query points must be 3D (x y z a line) for a mesh");
    fl_hal3 hal;
    int code = load_hal3(mesh_path, &hal);
    if (code) return code;
    fl_error err;
    uint8_t *where = fl_alloc_array(q->count + 1, 1);
    fl_status st = where ? fl_hal3_contains(&hal, q->coords, q->count, where, &err)
                         : fl_fail(&err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    double seconds = cli_now() - t0;
    if (st == FL_OK && c->output) st = write_where_csv3(c->output, q, where, &err);
    if (st == FL_OK) {
        size_t count[3] = {0, 0, 0};
        for (size_t i = 0; i < q->count; i++) count[where[i]]++;
        if (c->json) {
            cli_json j;
            cli_json_begin(&j, stdout);
            cli_json_uint(&j, "queries", q->count);
            cli_json_uint(&j, "inside", count[FL_HAL3_INSIDE]);
            cli_json_uint(&j, "boundary", count[FL_HAL3_BOUNDARY]);
            cli_json_uint(&j, "outside", count[FL_HAL3_OUTSIDE]);
            cli_json_double(&j, "seconds", seconds);
            cli_json_end(&j);
        } else if (!c->quiet) {
            printf("%zu queries: %zu inside, %zu on the surface, %zu outside\n", q->count,
                   count[FL_HAL3_INSIDE], count[FL_HAL3_BOUNDARY], count[FL_HAL3_OUTSIDE]);
        }
    }
    code = st ? cli_report(&err) : 0;
    fl_hal3_free(&hal);
    free(where);
    return code;
}

static int intersect3(const char *pa, const char *pb, int first, const cli_common *c, double t0)
{
    fl_hal3 a, b;
    int code = load_hal3(pa, &a);
    if (code) return code;
    if ((code = load_hal3(pb, &b))) {
        fl_hal3_free(&a);
        return code;
    }
    fl_error err;
    fl_hal3_pairs pairs = {0};
    fl_status st = fl_hal3_intersect(&a, &b, first, &pairs, &err);
    if (st == FL_OK && c->json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_bool(&j, "intersect", pairs.count > 0);
        cli_json_uint(&j, "pairs", pairs.count);
        cli_json_double(&j, "seconds", cli_now() - t0);
        cli_json_end(&j);
    } else if (st == FL_OK && !c->quiet) {
        if (pairs.count == 0)
            printf("the surfaces do not intersect\n");
        else
            printf("the surfaces intersect: %zu%s intersecting triangle pair%s\n", pairs.count,
                   first ? " (first found)" : "", pairs.count == 1 ? "" : "s");
    }
    fl_hal3_pairs_free(&pairs);
    fl_hal3_free(&a);
    fl_hal3_free(&b);
    return st ? cli_report(&err) : 0;
}

static fl_status write_where_csv(const char *path, const fl_points *q, const uint8_t *where,
                                 fl_error *err)
{
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st) return st;
    fputs("x,y,where\n", out.fp);
    for (size_t i = 0; i < q->count; i++)
        fprintf(out.fp, "%.17g,%.17g,%s\n", q->coords[2 * i], q->coords[2 * i + 1],
                where_name(where[i]));
    return fl_out_commit(&out, err);
}

int cmd_inside(int argc, char **argv)
{
    cli_common c = {0};
    const char *pos[2] = {0};
    if (parse_positional(argc, argv, &c, pos, 2, NULL, NULL, "inside")) return 1;
    if (c.help) {
        fputs(inside_usage, stdout);
        return 0;
    }
    fl_error err;
    fl_points q;
    double t0 = cli_now();
    if (fl_read_points(pos[1], &q, &err)) return cli_report(&err);
    if (is_mesh_path(pos[0])) {
        int r = inside3(pos[0], &q, &c, t0);
        fl_points_free(&q);
        return r;
    }
    if (q.dim != 2) {
        fl_points_free(&q);
        return cli_fail(2, "%s: query points must be 2D (x y a line)", pos[1]);
    }
    fl_hal2 hal;
    int code = load_hal(pos[0], &hal);
    if (code) {
        fl_points_free(&q);
        return code;
    }
    uint8_t *where = fl_alloc_array(q.count, 1);
    fl_status st = where ? fl_hal2_contains(&hal, q.coords, q.count, where, &err)
                         : fl_fail(&err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    double seconds = cli_now() - t0;
    if (st == FL_OK && c.output) st = write_where_csv(c.output, &q, where, &err);
    if (st == FL_OK) {
        size_t count[3] = {0, 0, 0};
        for (size_t i = 0; i < q.count; i++)
            count[where[i]]++;
        if (c.json) {
            cli_json j;
            cli_json_begin(&j, stdout);
            cli_json_uint(&j, "queries", q.count);
            cli_json_uint(&j, "inside", count[FL_HAL2_INSIDE]);
            cli_json_uint(&j, "boundary", count[FL_HAL2_BOUNDARY]);
            cli_json_uint(&j, "outside", count[FL_HAL2_OUTSIDE]);
            cli_json_double(&j, "seconds", seconds);
            cli_json_end(&j);
        } else if (!c.quiet) {
            printf("%zu queries: %zu inside, %zu on the boundary, %zu outside\n", q.count,
                   count[FL_HAL2_INSIDE], count[FL_HAL2_BOUNDARY], count[FL_HAL2_OUTSIDE]);
        }
    }
    if (st) code = cli_report(&err);
    fl_hal2_free(&hal);
    free(where);
    fl_points_free(&q);
    return code;
}

int cmd_intersect(int argc, char **argv)
{
    cli_common c = {0};
    const char *pos[2] = {0};
    int first = 0;
    if (parse_positional(argc, argv, &c, pos, 2, "--first", &first, "intersect")) return 1;
    if (c.help) {
        fputs(intersect_usage, stdout);
        return 0;
    }
    double t0 = cli_now();
    if (is_mesh_path(pos[0]) != is_mesh_path(pos[1]))
        return cli_fail(1, "intersect: A and B must both be polygons or both be meshes");
    if (is_mesh_path(pos[0])) return intersect3(pos[0], pos[1], first, &c, t0);
    fl_hal2 a, b;
    int code = load_hal(pos[0], &a);
    if (code) return code;
    if ((code = load_hal(pos[1], &b))) {
        fl_hal2_free(&a);
        return code;
    }
    fl_error err;
    fl_hal2_pairs pairs = {0};
    fl_status st = fl_hal2_intersect(&a, &b, first, &pairs, &err);
    if (st == FL_OK && c.json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_bool(&j, "intersect", pairs.count > 0);
        cli_json_uint(&j, "pairs", pairs.count);
        cli_json_double(&j, "seconds", cli_now() - t0);
        cli_json_end(&j);
    } else if (st == FL_OK && !c.quiet) {
        if (pairs.count == 0)
            printf("the boundaries do not intersect\n");
        else
            printf("the boundaries intersect: %zu%s intersecting edge pair%s\n", pairs.count,
                   first ? " (first found)" : "", pairs.count == 1 ? "" : "s");
    }
    fl_hal2_pairs_free(&pairs);
    fl_hal2_free(&a);
    fl_hal2_free(&b);
    return st ? cli_report(&err) : 0;
}

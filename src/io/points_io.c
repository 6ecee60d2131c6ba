/* The public readers and writers of points and polygons: the format comes from the file's
 * extension (or the `format` argument), files are read whole with fl_io_slurp, and output goes
 * through a temporary file renamed over the target only when complete. Point sets stored in
 * mesh formats (.ply .off .obj) are read with fl_parse_mesh and keep only the vertices. */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"

static const char *const text_point_formats[] = {"xyz", "xy", "txt", "csv", NULL};
static const char *const mesh_point_formats[] = {"ply", "off", "obj", NULL};
#define POINT_READ_LIST ".xyz .xy .txt .csv .ply .off .obj"
#define POINT_WRITE_LIST ".xyz .xy .txt .ply"
#define POLYGON_READ_LIST ".xy .geojson .json"
#define POLYGON_WRITE_LIST ".xy .geojson .json .svg"

static int is_one_of(const char *format, const char *const *list)
{
    for (; *list; list++)
        if (strcmp(format, *list) == 0) return 1;
    return 0;
}

/* "PLY", ".ply" and "ply" name the same format. */
static void normalize_format(const char *format, char *buf, size_t size)
{
    size_t i = 0;
    if (format && format[0] == '.') format++;
    for (; format && format[i] && i + 1 < size; i++)
        buf[i] = (char)tolower((unsigned char)format[i]);
    buf[i] = '\0';
}

static fl_status unknown_format(fl_error *err, const char *name, const char *format,
                                const char *what, const char *list)
{
    if (!format[0])
        return fl_fail(err, FL_ERR_USAGE, name, -1,
                       "no file extension to tell the %s format (supported: %s)", what, list);
    return fl_fail(err, FL_ERR_USAGE, name, -1, "unknown %s format '.%s' (supported: %s)", what,
                   format, list);
}

static fl_status points_from_mesh(const char *format, const char *name, const char *data,
                                  size_t size, fl_points *out, fl_error *err)
{
    fl_mesh mesh;
    fl_status st = fl_parse_mesh(format, name, data, size, &mesh, err);
    if (st != FL_OK) return st;
    if (mesh.vertex_count == 0) {
        fl_mesh_free(&mesh);
        return fl_fail(err, FL_ERR_INPUT, name, -1, "no vertices in file");
    }
    out->count = mesh.vertex_count;
    out->dim = 3;
    out->coords = mesh.xyz;
    mesh.xyz = NULL;
    fl_mesh_free(&mesh);
    return FL_OK;
}

fl_status fl_parse_points(const char *format, const char *name, const void *data, size_t size,
                          fl_points *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    char fmt[16];
    normalize_format(format, fmt, sizeof fmt);
    if (!name) name = "<memory>";
    if (!data && size) return fl_fail(err, FL_ERR_USAGE, name, -1, "data is NULL");
    const char *text = data ? data : "";
    if (is_one_of(fmt, text_point_formats)) return fl_text_points_parse(name, text, size, out, err);
    if (is_one_of(fmt, mesh_point_formats))
        return points_from_mesh(fmt, name, text, size, out, err);
    return unknown_format(err, name, fmt, "point", POINT_READ_LIST);
}

fl_status fl_read_points(const char *path, fl_points *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    if (!is_one_of(ext, text_point_formats) && !is_one_of(ext, mesh_point_formats))
        return unknown_format(err, path, ext, "point", POINT_READ_LIST);
    char *data;
    size_t size;
    fl_status st = fl_io_slurp(path, &data, &size, err);
    if (st != FL_OK) return st;
    st = fl_parse_points(ext, path, data, size, out, err);
    free(data);
    return st;
}

fl_status fl_parse_polygon(const char *format, const char *name, const void *data, size_t size,
                           fl_polygon *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    char fmt[16];
    normalize_format(format, fmt, sizeof fmt);
    if (!name) name = "<memory>";
    if (!data && size) return fl_fail(err, FL_ERR_USAGE, name, -1, "data is NULL");
    const char *text = data ? data : "";
    if (strcmp(fmt, "xy") == 0) return fl_xy_polygon_parse(name, text, size, out, err);
    if (strcmp(fmt, "geojson") == 0 || strcmp(fmt, "json") == 0)
        return fl_geojson_parse(name, text, size, out, err);
    return unknown_format(err, name, fmt, "polygon", POLYGON_READ_LIST);
}

fl_status fl_read_polygon(const char *path, fl_polygon *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    if (strcmp(ext, "xy") != 0 && strcmp(ext, "geojson") != 0 && strcmp(ext, "json") != 0)
        return unknown_format(err, path, ext, "polygon", POLYGON_READ_LIST);
    char *data;
    size_t size;
    fl_status st = fl_io_slurp(path, &data, &size, err);
    if (st != FL_OK) return st;
    st = fl_parse_polygon(ext, path, data, size, out, err);
    free(data);
    return st;
}

/* Finishes an atomic write: keeps the file when the writer succeeded, else removes it. */
static fl_status finish_output(fl_out_file *out, fl_status st, const char *path, fl_error *err)
{
    if (st == FL_OK) return fl_out_commit(out, err);
    fl_out_abort(out);
    return fl_fail(err, st, path, -1,
                   st == FL_ERR_NOMEM ? "out of memory while writing" : "write failed");
}

static fl_status check_points(const char *path, const fl_points *points, fl_error *err)
{
    if (points->dim != 2 && points->dim != 3)
        return fl_fail(err, FL_ERR_USAGE, path, -1, "points have dimension %d; 2 or 3 expected",
                       points->dim);
    if (points->count > 0 && !points->coords)
        return fl_fail(err, FL_ERR_USAGE, path, -1, "points->coords is NULL");
    for (size_t i = 0; i < points->count; i++)
        for (int k = 0; k < points->dim; k++)
            if (!isfinite(points->coords[i * (size_t)points->dim + (size_t)k]))
                return fl_fail(err, FL_ERR_INPUT, path, -1,
                               "point %zu has a coordinate that is NaN or infinite", i);
    return FL_OK;
}

/* PLY holds 3D vertices: 2D points get z = 0. */
static fl_status write_points_ply(FILE *fp, const fl_points *points)
{
    fl_mesh mesh = {points->count, points->coords, 0, NULL};
    double *padded = NULL;
    if (points->dim == 2) {
        padded = fl_alloc_array(points->count, 3 * sizeof(double));
        if (!padded) return FL_ERR_NOMEM;
        for (size_t i = 0; i < points->count; i++) {
            padded[3 * i] = points->coords[2 * i];
            padded[3 * i + 1] = points->coords[2 * i + 1];
            padded[3 * i + 2] = 0.0;
        }
        mesh.xyz = padded;
    }
    fl_status st = fl_ply_write(fp, &mesh);
    free(padded);
    return st;
}

fl_status fl_write_points(const char *path, const fl_points *points, fl_error *err)
{
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    int ply = strcmp(ext, "ply") == 0;
    if (!ply && strcmp(ext, "xyz") != 0 && strcmp(ext, "xy") != 0 && strcmp(ext, "txt") != 0)
        return unknown_format(err, path, ext, "point output", POINT_WRITE_LIST);
    fl_status st = check_points(path, points, err);
    if (st != FL_OK) return st;
    if (strcmp(ext, "xy") == 0 && points->dim != 2)
        return fl_fail(err, FL_ERR_USAGE, path, -1,
                       ".xy holds 2D points and these are 3D; write .xyz instead");
    fl_out_file out;
    if ((st = fl_out_open(&out, path, ply, err)) != FL_OK) return st;
    st = ply ? write_points_ply(out.fp, points) : fl_text_points_write(out.fp, points);
    return finish_output(&out, st, path, err);
}

static fl_status check_ring_table(const char *path, const fl_polygon *g, fl_error *err)
{
    if (g->ring_start[0] != 0 || g->ring_start[g->ring_count] != g->vertex_count)
        return fl_fail(err, FL_ERR_USAGE, path, -1,
                       "ring_start must start at 0 and end at vertex_count");
    for (size_t r = 0; r < g->ring_count; r++) {
        if (g->ring_start[r + 1] < g->ring_start[r])
            return fl_fail(err, FL_ERR_USAGE, path, -1, "ring_start decreases at ring %zu", r);
        if (g->ring_start[r + 1] - g->ring_start[r] < 3)
            return fl_fail(err, FL_ERR_INPUT, path, -1,
                           "ring %zu has %zu vertices; a ring needs at least 3", r,
                           g->ring_start[r + 1] - g->ring_start[r]);
    }
    if (g->polygon_start[0] != 0 || g->polygon_start[g->polygon_count] != g->ring_count)
        return fl_fail(err, FL_ERR_USAGE, path, -1,
                       "polygon_start must start at 0 and end at ring_count");
    for (size_t p = 0; p < g->polygon_count; p++)
        if (g->polygon_start[p + 1] <= g->polygon_start[p])
            return fl_fail(err, FL_ERR_USAGE, path, -1,
                           "polygon %zu has no ring (polygon_start must increase)", p);
    return FL_OK;
}

static fl_status check_polygon(const char *path, const fl_polygon *g, fl_error *err)
{
    if (g->vertex_count == 0 && g->ring_count == 0 && g->polygon_count == 0) return FL_OK;
    if (!g->xy || !g->ring_start || !g->polygon_start)
        return fl_fail(err, FL_ERR_USAGE, path, -1,
                       "polygon has vertices or rings but NULL arrays");
    fl_status st = check_ring_table(path, g, err);
    if (st != FL_OK) return st;
    for (size_t i = 0; i < 2 * g->vertex_count; i++)
        if (!isfinite(g->xy[i]))
            return fl_fail(err, FL_ERR_INPUT, path, -1,
                           "polygon vertex %zu has a coordinate that is NaN or infinite", i / 2);
    return FL_OK;
}

fl_status fl_write_polygon(const char *path, const fl_polygon *polygon, fl_error *err)
{
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    fl_status (*writer)(FILE *, const fl_polygon *) = NULL;
    if (strcmp(ext, "xy") == 0)
        writer = fl_xy_polygon_write;
    else if (strcmp(ext, "geojson") == 0 || strcmp(ext, "json") == 0)
        writer = fl_geojson_write;
    else if (strcmp(ext, "svg") == 0)
        writer = fl_svg_polygon_write;
    else
        return unknown_format(err, path, ext, "polygon output", POLYGON_WRITE_LIST);
    fl_status st = check_polygon(path, polygon, err);
    if (st != FL_OK) return st;
    fl_out_file out;
    if ((st = fl_out_open(&out, path, 0, err)) != FL_OK) return st;
    return finish_output(&out, writer(out.fp, polygon), path, err);
}

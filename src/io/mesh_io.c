/* Mesh reading and writing by file extension: .off .obj .ply .stl. The format modules parse a
 * whole buffer or write to a stream; this file owns files, dispatch and atomic output. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"

typedef struct mesh_format {
    const char *ext;
    fl_status (*parse)(const char *, const char *, size_t, fl_mesh *, fl_error *);
    fl_status (*write)(FILE *, const fl_mesh *);
    int binary;
    int float32; /* coordinates are stored as float32 */
} mesh_format;

static const mesh_format mesh_formats[] = {
    {"off", fl_off_parse, fl_off_write, 0, 0},
    {"obj", fl_obj_parse, fl_obj_write, 0, 0},
    {"ply", fl_ply_parse, fl_ply_write, 1, 0},
    {"stl", fl_stl_parse, fl_stl_write, 1, 1},
};

#define MESH_FORMAT_LIST ".off .obj .ply .stl"

/* ASCII case-insensitive equality (the extension may be "PLY"). */
static int same_nocase(const char *a, const char *b)
{
    for (; *a && *b; a++, b++) {
        char x = *a >= 'A' && *a <= 'Z' ? (char)(*a - 'A' + 'a') : *a;
        if (x != *b) return 0;
    }
    return *a == *b;
}

static const mesh_format *mesh_format_for(const char *ext)
{
    for (size_t i = 0; i < sizeof mesh_formats / sizeof mesh_formats[0]; i++)
        if (same_nocase(ext, mesh_formats[i].ext)) return &mesh_formats[i];
    return NULL;
}

static fl_status unknown_format(fl_error *err, const char *path, const char *ext)
{
    if (!ext[0])
        return fl_fail(
            err, FL_ERR_USAGE, path, -1,
            "cannot tell the mesh format: no file extension (supported: " MESH_FORMAT_LIST ")");
    return fl_fail(err, FL_ERR_USAGE, path, -1,
                   "unknown mesh format '.%s' (supported: " MESH_FORMAT_LIST ")", ext);
}

fl_status fl_parse_mesh(const char *format, const char *name, const void *data, size_t size,
                        fl_mesh *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, name, -1, "fl_parse_mesh: out is NULL");
    memset(out, 0, sizeof *out);
    if (!format || (!data && size))
        return fl_fail(err, FL_ERR_USAGE, name, -1, "fl_parse_mesh: format or data is NULL");
    const mesh_format *f = mesh_format_for(format);
    if (!f) return unknown_format(err, name, format);
    return f->parse(name, data ? data : "", size, out, err);
}

fl_status fl_read_mesh(const char *path, fl_mesh *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, path, -1, "fl_read_mesh: out is NULL");
    memset(out, 0, sizeof *out);
    if (!path) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_read_mesh: path is NULL");
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    const mesh_format *f = mesh_format_for(ext);
    if (!f) return unknown_format(err, path, ext);
    char *data;
    size_t size;
    fl_status st = fl_io_slurp(path, &data, &size, err);
    if (st) return st;
    st = f->parse(path, data, size, out, err);
    free(data);
    return st;
}

/* Writers trust the mesh, so it is checked here: a bad index would read out of bounds and a
 * NaN would produce a file no reader accepts. */
static fl_status check_mesh(const char *path, const fl_mesh *mesh, int float32, fl_error *err)
{
    if (!mesh) return fl_fail(err, FL_ERR_USAGE, path, -1, "fl_write_mesh: mesh is NULL");
    if ((mesh->vertex_count && !mesh->xyz) || (mesh->triangle_count && !mesh->tri))
        return fl_fail(err, FL_ERR_USAGE, path, -1, "fl_write_mesh: mesh arrays are NULL");
    if (mesh->vertex_count > UINT32_MAX || mesh->triangle_count > UINT32_MAX)
        return fl_fail(err, FL_ERR_INPUT, path, -1,
                       "mesh too large: more than 4294967295 vertices or triangles");
    for (size_t i = 0; i < 3 * mesh->vertex_count; i++)
        if (!isfinite(mesh->xyz[i]))
            return fl_fail(err, FL_ERR_INPUT, path, -1,
                           "cannot write: vertex %zu has a non-finite coordinate", i / 3);
    if (float32)
        for (size_t i = 0; i < 3 * mesh->vertex_count; i++)
            if (fabs(mesh->xyz[i]) > FLT_MAX)
                return fl_fail(err, FL_ERR_INPUT, path, -1,
                               "cannot write: vertex %zu has coordinate %g, beyond the float32 "
                               "range of this format",
                               i / 3, mesh->xyz[i]);
    for (size_t i = 0; i < 3 * mesh->triangle_count; i++)
        if (mesh->tri[i] >= mesh->vertex_count)
            return fl_fail(err, FL_ERR_INPUT, path, -1,
                           "cannot write: triangle %zu refers to vertex %u, but the mesh has "
                           "%zu vertices",
                           i / 3, (unsigned)mesh->tri[i], mesh->vertex_count);
    return FL_OK;
}

fl_status fl_write_mesh(const char *path, const fl_mesh *mesh, fl_error *err)
{
    if (!path) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_write_mesh: path is NULL");
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    const mesh_format *f = mesh_format_for(ext);
    if (!f) return unknown_format(err, path, ext);
    fl_status st = check_mesh(path, mesh, f->float32, err);
    if (st) return st;
    fl_out_file out;
    if ((st = fl_out_open(&out, path, f->binary, err))) return st;
    st = f->write(out.fp, mesh);
    if (st) {
        fl_out_abort(&out);
        return fl_fail(err, st, path, -1, "write failed");
    }
    return fl_out_commit(&out, err);
}

/* Wavefront OBJ, geometry only:
 *
 *   v x y z [w] [r g b]      a vertex; w and colour columns are ignored
 *   f a b c ...              a face; each reference is v, v/vt, v//vn or v/vt/vn with 1-based
 *                            vertex indices, negative ones counting back from the last vertex
 *
 * Every other statement (vt vn vp g o s usemtl mtllib l p ...) is ignored, '#' starts a
 * comment. Faces are fan-triangulated. Positive indices may refer to vertices defined later
 * in the file (the format allows it), so they are checked once all vertices are known; the
 * error then names the line of the largest offending reference. Line continuation with '\'
 * is not supported. */
#include <inttypes.h>
#include <math.h>
#include <string.h>

#include "io/io_internal.h"
#include "io/mesh_read.h"

typedef struct obj_reader {
    const char *name;
    fl_error *err;
    fl_mesh_build mb;
    long long max_index; /* largest 1-based positive vertex reference so far */
    long max_index_line; /* where it occurred */
} obj_reader;

/* One face reference: the vertex index before the first '/', made 0-based. */
static fl_status obj_reference(obj_reader *r, const char *tok, size_t len, long line,
                               uint32_t *index)
{
    const char *slash = memchr(tok, '/', len);
    size_t n = slash ? (size_t)(slash - tok) : len;
    long long v;
    char q[64];
    if (fl_parse_integer(tok, n, &v))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "expected a vertex reference (v, v/vt, v//vn or v/vt/vn), got %s",
                       fl_token_quote(tok, len, q, sizeof q));
    long long defined = (long long)fl_mesh_build_vertex_count(&r->mb);
    if (v == 0)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "vertex reference 0 is invalid (OBJ indices start at 1)");
    if (v < 0) {
        /* Relative: -1 is the last vertex defined so far. */
        if (-v > defined)
            return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                           "relative vertex reference %lld goes before the first vertex "
                           "(%lld defined so far)",
                           v, defined);
        *index = (uint32_t)(defined + v);
        return FL_OK;
    }
    if (v > (long long)UINT32_MAX)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line, "vertex reference %lld is out of range",
                       v);
    if (v > r->max_index) {
        r->max_index = v;
        r->max_index_line = line;
    }
    *index = (uint32_t)(v - 1);
    return FL_OK;
}

static fl_status obj_face(obj_reader *r, const char *p, const char *e, long line)
{
    const char *tok;
    size_t len;
    uint32_t first = 0, prev = 0, cur = 0;
    long long count = 0;
    while (fl_token_next(&p, e, &tok, &len)) {
        fl_status st = obj_reference(r, tok, len, line, &cur);
        if (st) return st;
        if (count == 0) first = cur;
        if (count >= 2 && (st = fl_mesh_build_triangle(&r->mb, first, prev, cur)))
            return fl_fail(r->err, st, r->name, line, "%s", fl_mesh_build_why(st));
        prev = cur;
        count++;
    }
    if (count < 3)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "a face needs at least 3 vertices, this one has %lld", count);
    return FL_OK;
}

static fl_status obj_read(obj_reader *r, const char *data, size_t size)
{
    fl_scan s;
    fl_scan_init(&s, data, size);
    const char *b, *e, *tok;
    size_t len;
    long line;
    fl_status st = FL_OK;
    if (size == 0) return fl_fail(r->err, FL_ERR_INPUT, r->name, 1, "empty file");
    while (!st && fl_scan_line(&s, &b, &e, &line)) {
        const char *hash = memchr(b, '#', (size_t)(e - b));
        if (hash) e = hash;
        if (!fl_token_next(&b, e, &tok, &len)) continue;
        if (fl_token_is(tok, len, "v"))
            st = fl_mesh_build_text_vertex(&r->mb, b, e, "'v'", r->name, line, r->err);
        else if (fl_token_is(tok, len, "f"))
            st = obj_face(r, b, e, line);
    }
    if (st) return st;
    long long n = (long long)fl_mesh_build_vertex_count(&r->mb);
    if (r->max_index > n)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, r->max_index_line,
                       "vertex reference %lld is out of range (the file has %lld vertices)",
                       r->max_index, n);
    return FL_OK;
}

fl_status fl_obj_parse(const char *name, const char *data, size_t size, fl_mesh *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    obj_reader r = {.name = name, .err = err};
    fl_mesh_build_init(&r.mb);
    fl_status st = obj_read(&r, data, size);
    if (st) {
        fl_mesh_build_free(&r.mb);
        return st;
    }
    fl_mesh_build_finish(&r.mb, out);
    return FL_OK;
}

fl_status fl_obj_write(FILE *fp, const fl_mesh *mesh)
{
    fprintf(fp, "# flintstone mesh: %zu vertices, %zu triangles\n", mesh->vertex_count,
            mesh->triangle_count);
    for (size_t i = 0; i < mesh->vertex_count; i++) {
        const double *v = mesh->xyz + 3 * i;
        fprintf(fp, "v %.17g %.17g %.17g\n", v[0], v[1], v[2]);
    }
    for (size_t i = 0; i < mesh->triangle_count; i++) {
        const uint32_t *t = mesh->tri + 3 * i;
        fprintf(fp, "f %" PRIu64 " %" PRIu64 " %" PRIu64 "\n", (uint64_t)t[0] + 1,
                (uint64_t)t[1] + 1, (uint64_t)t[2] + 1);
    }
    return ferror(fp) ? FL_ERR_IO : FL_OK;
}

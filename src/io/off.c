/* OFF (Geomview's Object File Format), ASCII only:
 *
 *   OFF                      keyword, optionally with the C/N/ST prefixes (COFF, NOFF, STCNOFF)
 *   nv nf [ne]               counts (may follow the keyword on its line)
 *   x y z [...]              nv vertex lines; extra columns (normal, colour, texture) ignored
 *   n i0 i1 ... [colour]     nf face lines, 0-based indices; extra columns ignored
 *
 * '#' starts a comment. Each record is one line, which is what lets colour columns after a face
 * be told apart from the next face. Faces are fan-triangulated (i0 i1 i2, i0 i2 i3, ...). */
#include <inttypes.h>
#include <math.h>
#include <string.h>

#include "io/io_internal.h"
#include "io/mesh_read.h"

typedef struct off_reader {
    const char *name;
    fl_scan s;
    fl_error *err;
    fl_mesh_build mb;
    long long vertex_count;
    long long face_count;
    size_t size;
} off_reader;

/* The next line with a token after stripping its comment; [*b, *e) is the stripped line. */
static int off_content_line(off_reader *r, const char **b, const char **e, long *line)
{
    while (fl_scan_line(&r->s, b, e, line)) {
        const char *hash = memchr(*b, '#', (size_t)(*e - *b));
        if (hash) *e = hash;
        const char *p = *b, *tok;
        size_t len;
        if (fl_token_next(&p, *e, &tok, &len)) return 1;
    }
    return 0;
}

/* Checks the keyword: [ST][C][N]OFF. 4OFF/nOFF (other dimensions) are not 3D meshes. */
static fl_status off_keyword(off_reader *r, const char *tok, size_t len, long line)
{
    char q[64];
    const char *k = tok;
    size_t n = len;
    if (n >= 2 && memcmp(k, "ST", 2) == 0) k += 2, n -= 2;
    if (n >= 1 && *k == 'C') k++, n--;
    if (n >= 1 && *k == 'N') k++, n--;
    if (fl_token_is(k, n, "OFF")) return FL_OK;
    if (n > 3 && memcmp(k + n - 3, "OFF", 3) == 0 && (*k == '4' || *k == 'n'))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "%s: only 3D OFF files are supported (no 4D or nD variants)",
                       fl_token_quote(tok, len, q, sizeof q));
    return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                   "missing OFF header: the file should start with 'OFF', not %s",
                   fl_token_quote(tok, len, q, sizeof q));
}

static fl_status off_count(off_reader *r, const char *tok, size_t len, long line, long long *v)
{
    char q[64];
    if (fl_parse_integer(tok, len, v) || *v < 0)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "expected a vertex or face count (a non-negative integer), got %s",
                       fl_token_quote(tok, len, q, sizeof q));
    if (*v > (long long)UINT32_MAX)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "count %lld exceeds the limit of 4294967295", *v);
    return FL_OK;
}

/* Reads "nv nf [ne]" from [p, e), the rest of the keyword line or the next content line. */
static fl_status off_counts(off_reader *r, const char *p, const char *e, long line)
{
    const char *tok;
    size_t len;
    if (!fl_token_next(&p, e, &tok, &len)) {
        if (!off_content_line(r, &p, &e, &line))
            return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line,
                           "unexpected end of file: expected the counts line 'nv nf ne'");
        fl_token_next(&p, e, &tok, &len);
    }
    char q[64];
    if (fl_token_is(tok, len, "BINARY"))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line, "binary OFF is not supported");
    fl_status st = off_count(r, tok, len, line, &r->vertex_count);
    if (st) return st;
    if (!fl_token_next(&p, e, &tok, &len))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "the counts line needs the number of faces after the number of vertices");
    if ((st = off_count(r, tok, len, line, &r->face_count))) return st;
    long long edges;
    if (fl_token_next(&p, e, &tok, &len) && (st = off_count(r, tok, len, line, &edges))) return st;
    if (fl_token_next(&p, e, &tok, &len))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "unexpected %s after the counts 'nv nf ne'",
                       fl_token_quote(tok, len, q, sizeof q));
    /* The counts are untrusted: a vertex line takes at least 6 bytes ("0 0 0\n") and a face
     * line 8 ("3 0 1 2\n"), so refuse before allocating for a file that cannot hold them. */
    unsigned long long need =
        6ull * (unsigned long long)r->vertex_count + 8ull * (unsigned long long)r->face_count;
    unsigned long long have = (unsigned long long)(r->s.end - r->s.p) + 1;
    if (need > have)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "the header claims %lld vertices and %lld faces, which need at least "
                       "%llu bytes, but only %llu bytes follow",
                       r->vertex_count, r->face_count, need, have - 1);
    fl_mesh_build_reserve(&r->mb, (size_t)r->vertex_count, (size_t)r->face_count);
    return FL_OK;
}

static fl_status off_index(off_reader *r, const char **p, const char *e, long line, long long k,
                           long long n, uint32_t *index)
{
    const char *tok;
    size_t len;
    long long v;
    char q[64];
    if (!fl_token_next(p, e, &tok, &len))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "the face declares %lld vertices but lists only %lld", n, k);
    if (fl_parse_integer(tok, len, &v))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line, "expected a vertex index, got %s",
                       fl_token_quote(tok, len, q, sizeof q));
    if (v < 0 || v >= r->vertex_count)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "vertex index %lld is out of range (the file has %lld vertices, "
                       "indices start at 0)",
                       v, r->vertex_count);
    *index = (uint32_t)v;
    return FL_OK;
}

/* "n i0 ... i(n-1)" fan-triangulated as (i0, i(k-1), ik). */
static fl_status off_face(off_reader *r, const char *p, const char *e, long line)
{
    const char *tok;
    size_t len;
    long long n;
    char q[64];
    fl_token_next(&p, e, &tok, &len);
    if (fl_parse_integer(tok, len, &n))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "expected the number of vertices of a face, got %s",
                       fl_token_quote(tok, len, q, sizeof q));
    if (n < 3)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "a face needs at least 3 vertices, this one has %lld", n);
    uint32_t first, prev, cur;
    fl_status st = off_index(r, &p, e, line, 0, n, &first);
    if (!st) st = off_index(r, &p, e, line, 1, n, &prev);
    for (long long k = 2; k < n && !st; k++) {
        if ((st = off_index(r, &p, e, line, k, n, &cur))) break;
        st = fl_mesh_build_triangle(&r->mb, first, prev, cur);
        if (st) return fl_fail(r->err, st, r->name, line, "%s", fl_mesh_build_why(st));
        prev = cur;
    }
    return st;
}

static fl_status off_read(off_reader *r)
{
    const char *b, *e, *tok;
    size_t len;
    long line;
    if (!off_content_line(r, &b, &e, &line))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line,
                       r->size == 0 ? "empty file"
                                    : "no OFF header, only blank lines and comments");
    fl_token_next(&b, e, &tok, &len);
    fl_status st = off_keyword(r, tok, len, line);
    if (!st) st = off_counts(r, b, e, line);
    for (long long i = 0; i < r->vertex_count && !st; i++) {
        if (!off_content_line(r, &b, &e, &line))
            return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line,
                           "unexpected end of file: the header declares %lld vertices, "
                           "found %lld",
                           r->vertex_count, i);
        st = fl_mesh_build_text_vertex(&r->mb, b, e, "a vertex", r->name, line, r->err);
    }
    for (long long i = 0; i < r->face_count && !st; i++) {
        if (!off_content_line(r, &b, &e, &line))
            return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line,
                           "unexpected end of file: the header declares %lld faces, found %lld",
                           r->face_count, i);
        st = off_face(r, b, e, line);
    }
    if (!st && off_content_line(r, &b, &e, &line))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "unexpected data after the last face (the header declares %lld "
                       "vertices and %lld faces)",
                       r->vertex_count, r->face_count);
    return st;
}

fl_status fl_off_parse(const char *name, const char *data, size_t size, fl_mesh *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    off_reader r = {.name = name, .err = err, .size = size};
    fl_scan_init(&r.s, data, size);
    fl_mesh_build_init(&r.mb);
    fl_status st = off_read(&r);
    if (st) {
        fl_mesh_build_free(&r.mb);
        return st;
    }
    fl_mesh_build_finish(&r.mb, out);
    return FL_OK;
}

fl_status fl_off_write(FILE *fp, const fl_mesh *mesh)
{
    /* "%.17g" prints every double so that strtod gives back the same bits. */
    fprintf(fp, "OFF\n%zu %zu 0\n", mesh->vertex_count, mesh->triangle_count);
    for (size_t i = 0; i < mesh->vertex_count; i++) {
        const double *v = mesh->xyz + 3 * i;
        fprintf(fp, "%.17g %.17g %.17g\n", v[0], v[1], v[2]);
    }
    for (size_t i = 0; i < mesh->triangle_count; i++) {
        const uint32_t *t = mesh->tri + 3 * i;
        fprintf(fp, "3 %" PRIu32 " %" PRIu32 " %" PRIu32 "\n", t[0], t[1], t[2]);
    }
    return ferror(fp) ? FL_ERR_IO : FL_OK;
}

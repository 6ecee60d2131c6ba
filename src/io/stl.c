/* STL, binary and ASCII. STL lists every triangle with its own three corners, so shared
 * vertices are recovered by welding corners with bitwise-equal coordinates (after -0.0 is
 * mapped to 0.0); nearby but unequal corners stay distinct, which keeps welding exact and
 * the result independent of any tolerance.
 *
 * Binary: 80-byte header, uint32 triangle count n, then n records of 50 bytes (normal and
 * three corners as 3 float32 each, little endian, and a uint16 attribute). Some binary files
 * start with "solid" like ASCII ones, so a file whose size is exactly 84 + 50 n is binary
 * whatever its first bytes say. The stored normals are ignored (the corner order defines the
 * orientation); the writer recomputes them. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"
#include "io/mesh_read.h"

/* ---- welding: an open-addressing hash table from coordinates to vertex ids ---- */

typedef struct stl_welder {
    fl_mesh_build *mb;
    uint32_t *slot; /* vertex id + 1, or 0 when empty */
    size_t mask;    /* table size - 1; the size is a power of two, at most half full */
} stl_welder;

static uint64_t double_bits(double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}

static size_t weld_hash(const double v[3])
{
    uint64_t h = double_bits(v[0]) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29)) + double_bits(v[1]) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 32)) + double_bits(v[2]) * 0x94D049BB133111EBull;
    h ^= h >> 31;
    h *= 0xD6E8FEB86659FD93ull;
    return (size_t)(h ^ (h >> 32));
}

static int weld_resize(stl_welder *w, size_t size)
{
    uint32_t *slot = fl_calloc_array(size, sizeof *slot);
    if (!slot) return -1;
    free(w->slot);
    w->slot = slot;
    w->mask = size - 1;
    const double *xyz = w->mb->xyz.data;
    size_t n = fl_mesh_build_vertex_count(w->mb);
    for (size_t id = 0; id < n; id++) {
        size_t i = weld_hash(xyz + 3 * id) & w->mask;
        while (w->slot[i])
            i = (i + 1) & w->mask;
        w->slot[i] = (uint32_t)id + 1;
    }
    return 0;
}

static int weld_init(stl_welder *w, fl_mesh_build *mb, size_t expected_vertices)
{
    w->mb = mb;
    w->slot = NULL;
    size_t size = 64;
    while (size / 2 < expected_vertices && size < (SIZE_MAX >> 2))
        size *= 2;
    return weld_resize(w, size);
}

/* The id of the vertex at v (finite), adding it if new. */
static fl_status weld(stl_welder *w, double v[3], uint32_t *id)
{
    for (int k = 0; k < 3; k++)
        if (v[k] == 0.0) v[k] = 0.0; /* -0.0 == 0.0 but has other bits */
    size_t n = fl_mesh_build_vertex_count(w->mb);
    if (2 * (n + 1) > w->mask + 1 && weld_resize(w, 2 * (w->mask + 1))) return FL_ERR_NOMEM;
    const double *xyz = w->mb->xyz.data;
    size_t i = weld_hash(v) & w->mask;
    for (; w->slot[i]; i = (i + 1) & w->mask) {
        uint32_t cand = w->slot[i] - 1;
        if (memcmp(xyz + 3 * (size_t)cand, v, 3 * sizeof(double)) == 0) {
            *id = cand;
            return FL_OK;
        }
    }
    fl_status st = fl_mesh_build_vertex(w->mb, v[0], v[1], v[2]);
    if (st) return st;
    *id = (uint32_t)n;
    w->slot[i] = (uint32_t)n + 1;
    return FL_OK;
}

/* ---- binary ---- */

static uint32_t load_le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static float load_le_float(const unsigned char *p)
{
    uint32_t u = load_le32(p);
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static fl_status stl_binary(const char *name, const unsigned char *data, uint32_t n,
                            fl_mesh_build *mb, fl_error *err)
{
    stl_welder w;
    if (weld_init(&w, mb, n / 2 + 1))
        return fl_fail_at_offset(err, FL_ERR_NOMEM, name, 80, "out of memory");
    fl_mesh_build_reserve(mb, n / 2 + 3, n);
    fl_status st = FL_OK;
    for (size_t t = 0; t < n && !st; t++) {
        uint32_t id[3];
        for (int k = 0; k < 3 && !st; k++) {
            size_t off = 84 + 50 * t + 12 + 12 * (size_t)k;
            double v[3];
            for (int c = 0; c < 3; c++) {
                v[c] = load_le_float(data + off + 4 * (size_t)c);
                if (!isfinite(v[c])) {
                    st = fl_fail_at_offset(err, FL_ERR_INPUT, name, (long long)(off + 4 * c),
                                           "triangle %zu: corner %d has a non-finite coordinate", t,
                                           k + 1);
                    break;
                }
            }
            if (!st && (st = weld(&w, v, &id[k])))
                st = fl_fail_at_offset(err, st, name, (long long)off, "%s", fl_mesh_build_why(st));
        }
        if (!st && (st = fl_mesh_build_triangle(mb, id[0], id[1], id[2])))
            st = fl_fail_at_offset(err, st, name, (long long)(84 + 50 * t), "%s",
                                   fl_mesh_build_why(st));
    }
    free(w.slot);
    return st;
}

/* ---- ASCII ---- */

typedef struct stl_ascii {
    const char *name;
    fl_error *err;
    fl_scan s;
    stl_welder w;
    const char *tok;
    size_t len;
} stl_ascii;

static fl_status stl_eof(stl_ascii *a, const char *expected)
{
    return fl_fail(a->err, FL_ERR_INPUT, a->name, a->s.line, "unexpected end of file: expected %s",
                   expected);
}

static fl_status stl_unexpected(stl_ascii *a, const char *expected)
{
    char q[64];
    return fl_fail(a->err, FL_ERR_INPUT, a->name, a->s.line, "expected %s, got %s", expected,
                   fl_token_quote(a->tok, a->len, q, sizeof q));
}

static int stl_next(stl_ascii *a)
{
    return fl_scan_token(&a->s, 0, &a->tok, &a->len);
}

static fl_status stl_expect(stl_ascii *a, const char *word)
{
    char what[32];
    snprintf(what, sizeof what, "'%s'", word);
    if (!stl_next(a)) return stl_eof(a, what);
    return fl_token_is_nocase(a->tok, a->len, word) ? FL_OK : stl_unexpected(a, what);
}

static fl_status stl_number(stl_ascii *a, double *v)
{
    if (!stl_next(a)) return stl_eof(a, "a number");
    if (fl_parse_double(a->tok, a->len, v)) return stl_unexpected(a, "a number");
    return FL_OK;
}

static fl_status stl_vertex(stl_ascii *a, uint32_t *id)
{
    double v[3];
    char q[64];
    for (int c = 0; c < 3; c++) {
        fl_status st = stl_number(a, &v[c]);
        if (st) return st;
        if (!isfinite(v[c]))
            return fl_fail(a->err, FL_ERR_INPUT, a->name, a->s.line,
                           "coordinate %s is not a finite number",
                           fl_token_quote(a->tok, a->len, q, sizeof q));
    }
    fl_status st = weld(&a->w, v, id);
    return st ? fl_fail(a->err, st, a->name, a->s.line, "%s", fl_mesh_build_why(st)) : FL_OK;
}

/* "facet normal nx ny nz / outer loop / vertex x y z (3 or more) / endloop / endfacet", after
 * the 'facet' token. A loop of more than 3 vertices is fan-triangulated. */
static fl_status stl_facet(stl_ascii *a)
{
    double normal;
    fl_status st = stl_expect(a, "normal");
    for (int c = 0; c < 3 && !st; c++)
        st = stl_number(a, &normal);
    if (!st) st = stl_expect(a, "outer");
    if (!st) st = stl_expect(a, "loop");
    uint32_t first = 0, prev = 0, cur = 0;
    int count = 0;
    while (!st) {
        if (!stl_next(a)) return stl_eof(a, "'vertex' or 'endloop'");
        if (fl_token_is_nocase(a->tok, a->len, "endloop")) break;
        if (!fl_token_is_nocase(a->tok, a->len, "vertex"))
            return stl_unexpected(a, "'vertex' or 'endloop'");
        if ((st = stl_vertex(a, &cur))) return st;
        if (count == 0) first = cur;
        if (count >= 2 && (st = fl_mesh_build_triangle(a->w.mb, first, prev, cur)))
            return fl_fail(a->err, st, a->name, a->s.line, "%s", fl_mesh_build_why(st));
        prev = cur;
        if (count < 3) count++;
    }
    if (!st && count < 3)
        return fl_fail(a->err, FL_ERR_INPUT, a->name, a->s.line,
                       "a facet needs 3 vertices, this one has %d", count);
    return st ? st : stl_expect(a, "endfacet");
}

/* One or more "solid name ... endsolid name" blocks. */
static fl_status stl_ascii_read(stl_ascii *a)
{
    fl_status st = stl_expect(a, "solid");
    while (!st) {
        fl_scan_skip_line(&a->s); /* the solid's name */
        for (;;) {
            if (!stl_next(a)) return stl_eof(a, "'facet' or 'endsolid'");
            if (fl_token_is_nocase(a->tok, a->len, "endsolid")) break;
            if (!fl_token_is_nocase(a->tok, a->len, "facet"))
                return stl_unexpected(a, "'facet' or 'endsolid'");
            if ((st = stl_facet(a))) return st;
        }
        fl_scan_skip_line(&a->s);
        if (!stl_next(a)) return FL_OK;
        if (!fl_token_is_nocase(a->tok, a->len, "solid"))
            return stl_unexpected(a, "'solid' or the end of the file after 'endsolid'");
    }
    return st;
}

static int starts_with_solid(const char *data, size_t size)
{
    fl_scan s;
    const char *tok;
    size_t len;
    fl_scan_init(&s, data, size < 512 ? size : 512);
    return fl_scan_token(&s, 0, &tok, &len) && fl_token_is_nocase(tok, len, "solid");
}

static fl_status stl_ascii_parse(const char *name, const char *data, size_t size, fl_mesh_build *mb,
                                 fl_error *err)
{
    stl_ascii a = {.name = name, .err = err};
    fl_scan_init(&a.s, data, size);
    if (weld_init(&a.w, mb, size / 256))
        return fl_fail(err, FL_ERR_NOMEM, name, 1, "out of memory");
    fl_status st = stl_ascii_read(&a);
    free(a.w.slot);
    /* A binary file whose header starts with "solid" but whose size does not match its count
     * lands here; say so rather than only complaining about a strange token. */
    if (st == FL_ERR_INPUT && err && memchr(data, '\0', size < 4096 ? size : 4096)) {
        size_t used = strlen(err->message);
        snprintf(err->message + used, sizeof err->message - used,
                 " (the file holds binary data: a binary STL whose size does not match its "
                 "triangle count?)");
    }
    return st;
}

fl_status fl_stl_parse(const char *name, const char *data, size_t size, fl_mesh *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    if (size == 0) return fl_fail(err, FL_ERR_INPUT, name, 1, "empty file");
    fl_mesh_build mb;
    fl_mesh_build_init(&mb);
    fl_status st;
    const unsigned char *bytes = (const unsigned char *)data;
    uint32_t n = size >= 84 ? load_le32(bytes + 80) : 0;
    if (size >= 84 && 84 + 50 * (uint64_t)n == size)
        st = stl_binary(name, bytes, n, &mb, err);
    else if (starts_with_solid(data, size))
        st = stl_ascii_parse(name, data, size, &mb, err);
    else if (size < 84)
        st = fl_fail_at_offset(err, FL_ERR_INPUT, name, 0,
                               "not an STL file: it does not start with 'solid' and is too short "
                               "(%zu bytes) for a binary STL (at least 84)",
                               size);
    else
        st = fl_fail_at_offset(err, FL_ERR_INPUT, name, 80,
                               "binary STL size mismatch: the header declares %u triangles, "
                               "which need %llu bytes, but the file has %zu bytes",
                               (unsigned)n, 84 + 50 * (unsigned long long)n, size);
    if (st) {
        fl_mesh_build_free(&mb);
        return st;
    }
    fl_mesh_build_finish(&mb, out);
    return FL_OK;
}

/* ---- writer ---- */

static void store_le32(unsigned char *p, uint32_t u)
{
    for (int i = 0; i < 4; i++)
        p[i] = (unsigned char)(u >> (8 * i));
}

static void store_le_float(unsigned char *p, double d)
{
    float f = (float)d;
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    store_le32(p, u);
}

/* The unit normal of triangle t by the right-hand rule, or 0 for a degenerate triangle. */
static void triangle_normal(const fl_mesh *mesh, size_t t, double n[3])
{
    const double *a = mesh->xyz + 3 * (size_t)mesh->tri[3 * t];
    const double *b = mesh->xyz + 3 * (size_t)mesh->tri[3 * t + 1];
    const double *c = mesh->xyz + 3 * (size_t)mesh->tri[3 * t + 2];
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++)
        n[k] = len > 0 && isfinite(len) ? n[k] / len : 0.0;
}

/* Binary STL stores float32: coordinates are rounded to 24-bit significands, so a written
 * mesh reads back only approximately (and vertices that become equal are welded). The caller
 * has checked that every coordinate is within the float32 range. */
fl_status fl_stl_write(FILE *fp, const fl_mesh *mesh)
{
    unsigned char header[84];
    memset(header, ' ', 80);
    memcpy(header, "binary STL written by flintstone", 32);
    store_le32(header + 80, (uint32_t)mesh->triangle_count);
    fwrite(header, 1, sizeof header, fp);
    for (size_t t = 0; t < mesh->triangle_count; t++) {
        unsigned char rec[50];
        double n[3];
        triangle_normal(mesh, t, n);
        for (int c = 0; c < 3; c++)
            store_le_float(rec + 4 * c, n[c]);
        for (int k = 0; k < 3; k++) {
            const double *v = mesh->xyz + 3 * (size_t)mesh->tri[3 * t + (size_t)k];
            for (int c = 0; c < 3; c++)
                store_le_float(rec + 12 + 12 * k + 4 * c, v[c]);
        }
        rec[48] = rec[49] = 0;
        fwrite(rec, 1, sizeof rec, fp);
    }
    return ferror(fp) ? FL_ERR_IO : FL_OK;
}

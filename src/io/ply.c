/* PLY (Stanford polygon file format), ascii 1.0 and binary little/big endian 1.0.
 *
 * The header declares elements, each with a count and a list of properties; the body holds
 * the elements in declaration order. We take x, y, z from the "vertex" element (any scalar
 * type, any order among other properties) and the "vertex_indices" (or "vertex_index") list
 * from the "face" element; every other element and property, lists included, is skipped.
 * Faces are fan-triangulated. A face naming the same vertex twice is kept (mesh checks
 * report it as degenerate).
 *
 * Header counts are untrusted: before allocating, the body must be large enough to hold the
 * declared items at their smallest size, so a tiny file claiming 2^40 vertices is rejected
 * at once. Every binary read is bounds-checked and errors give byte offsets; ascii errors
 * give line numbers. */
#include <inttypes.h>
#include <math.h>
#include <string.h>

#include "io/io_internal.h"
#include "io/mesh_read.h"

typedef enum ply_format { PLY_ASCII, PLY_BINARY_LE, PLY_BINARY_BE } ply_format;

typedef enum ply_type {
    PLY_INT8,
    PLY_UINT8,
    PLY_INT16,
    PLY_UINT16,
    PLY_INT32,
    PLY_UINT32,
    PLY_FLOAT32,
    PLY_FLOAT64
} ply_type;

static const struct {
    const char *name, *alias;
    size_t size;
} ply_types[] = {
    {"char", "int8", 1}, {"uchar", "uint8", 1}, {"short", "int16", 2},   {"ushort", "uint16", 2},
    {"int", "int32", 4}, {"uint", "uint32", 4}, {"float", "float32", 4}, {"double", "float64", 8},
};

/* What a property means to us. */
enum ply_role { ROLE_OTHER, ROLE_X, ROLE_Y, ROLE_Z, ROLE_INDICES };

typedef struct ply_property {
    ply_type type;       /* the scalar type, or the item type of a list */
    ply_type count_type; /* lists only */
    int is_list;
    int role;
} ply_property;

enum ply_kind { KIND_OTHER, KIND_VERTEX, KIND_FACE };

typedef struct ply_element {
    char name[32]; /* for messages; truncated */
    int kind;
    uint64_t count;
    long line; /* of the declaration */
    fl_vec props;
} ply_element;

typedef struct ply_reader {
    const char *name;
    const unsigned char *data;
    size_t size;
    fl_error *err;
    ply_format format;
    int have_format;
    fl_vec elements;   /* ply_element */
    fl_scan s;         /* header, then the ascii body */
    size_t body;       /* byte offset of the body */
    uint64_t vertices; /* declared vertex count */
    fl_mesh_build mb;
} ply_reader;

/* ---- header ---- */

static int ply_type_from(const char *tok, size_t len, ply_type *t)
{
    for (int i = 0; i < (int)(sizeof ply_types / sizeof ply_types[0]); i++)
        if (fl_token_is(tok, len, ply_types[i].name) || fl_token_is(tok, len, ply_types[i].alias)) {
            *t = (ply_type)i;
            return 0;
        }
    return -1;
}

static int ply_is_integer(ply_type t)
{
    return t < PLY_FLOAT32;
}

static fl_status header_fail(ply_reader *r, long line, const char *what, const char *tok,
                             size_t len)
{
    char q[64];
    if (!tok) return fl_fail(r->err, FL_ERR_INPUT, r->name, line, "%s", what);
    return fl_fail(r->err, FL_ERR_INPUT, r->name, line, "%s, got %s", what,
                   fl_token_quote(tok, len, q, sizeof q));
}

static fl_status ply_format_line(ply_reader *r, const char *p, const char *e, long line)
{
    const char *tok, *ver;
    size_t len, vlen;
    if (!fl_token_next(&p, e, &tok, &len))
        return header_fail(r, line,
                           "'format' needs ascii, binary_little_endian or "
                           "binary_big_endian",
                           NULL, 0);
    if (fl_token_is(tok, len, "ascii"))
        r->format = PLY_ASCII;
    else if (fl_token_is(tok, len, "binary_little_endian"))
        r->format = PLY_BINARY_LE;
    else if (fl_token_is(tok, len, "binary_big_endian"))
        r->format = PLY_BINARY_BE;
    else
        return header_fail(r, line, "expected ascii, binary_little_endian or binary_big_endian",
                           tok, len);
    if (!fl_token_next(&p, e, &ver, &vlen) || !fl_token_is(ver, vlen, "1.0"))
        return header_fail(r, line, "only PLY version 1.0 is supported", NULL, 0);
    r->have_format = 1;
    return FL_OK;
}

static fl_status ply_element_line(ply_reader *r, const char *p, const char *e, long line)
{
    const char *tok, *ctok;
    size_t len, clen;
    long long count;
    if (!fl_token_next(&p, e, &tok, &len) || !fl_token_next(&p, e, &ctok, &clen))
        return header_fail(r, line, "'element' needs a name and a count", NULL, 0);
    if (fl_parse_integer(ctok, clen, &count) || count < 0)
        return header_fail(r, line, "expected an element count (a non-negative integer)", ctok,
                           clen);
    ply_element el = {.count = (uint64_t)count, .line = line};
    snprintf(el.name, sizeof el.name, "%.*s", (int)(len < 31 ? len : 31), tok);
    el.kind = fl_token_is(tok, len, "vertex") ? KIND_VERTEX
              : fl_token_is(tok, len, "face") ? KIND_FACE
                                              : KIND_OTHER;
    ply_element *all = r->elements.data;
    for (size_t i = 0; i < r->elements.count; i++)
        if (el.kind != KIND_OTHER && all[i].kind == el.kind)
            return header_fail(r, line, "duplicate element", tok, len);
    if (el.kind != KIND_OTHER && count > (long long)UINT32_MAX)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, line,
                       "%lld %s elements exceed the limit of 4294967295", count, el.name);
    fl_vec_init(&el.props, sizeof(ply_property));
    if (fl_vec_push(&r->elements, &el, 1))
        return fl_fail(r->err, FL_ERR_NOMEM, r->name, line, "out of memory");
    if (el.kind == KIND_VERTEX) r->vertices = el.count;
    return FL_OK;
}

static int ply_role(const ply_element *el, const char *tok, size_t len, int is_list)
{
    if (el->kind == KIND_VERTEX && !is_list) {
        if (fl_token_is(tok, len, "x")) return ROLE_X;
        if (fl_token_is(tok, len, "y")) return ROLE_Y;
        if (fl_token_is(tok, len, "z")) return ROLE_Z;
    }
    if (el->kind == KIND_FACE && is_list &&
        (fl_token_is(tok, len, "vertex_indices") || fl_token_is(tok, len, "vertex_index")))
        return ROLE_INDICES;
    return ROLE_OTHER;
}

/* "property <type> <name>" or "property list <count type> <item type> <name>". */
static fl_status ply_property_line(ply_reader *r, const char *p, const char *e, long line)
{
    if (r->elements.count == 0)
        return header_fail(r, line, "'property' before any 'element'", NULL, 0);
    ply_element *el = (ply_element *)r->elements.data + r->elements.count - 1;
    ply_property prop = {0};
    const char *tok;
    size_t len;
    if (!fl_token_next(&p, e, &tok, &len))
        return header_fail(r, line, "'property' needs a type and a name", NULL, 0);
    if (fl_token_is(tok, len, "list")) {
        prop.is_list = 1;
        if (!fl_token_next(&p, e, &tok, &len) || ply_type_from(tok, len, &prop.count_type))
            return header_fail(r, line, "expected the list's count type", tok, len);
        if (!ply_is_integer(prop.count_type))
            return header_fail(r, line, "a list count type must be an integer type", tok, len);
        if (!fl_token_next(&p, e, &tok, &len))
            return header_fail(r, line, "'property list' needs an item type", NULL, 0);
    }
    if (ply_type_from(tok, len, &prop.type))
        return header_fail(r, line, "unknown property type", tok, len);
    if (!fl_token_next(&p, e, &tok, &len))
        return header_fail(r, line, "'property' needs a name", NULL, 0);
    prop.role = ply_role(el, tok, len, prop.is_list);
    if (prop.role == ROLE_INDICES && !ply_is_integer(prop.type))
        return header_fail(r, line, "vertex indices must have an integer type", tok, len);
    const ply_property *props = el->props.data;
    for (size_t i = 0; i < el->props.count; i++)
        if (prop.role != ROLE_OTHER && props[i].role == prop.role)
            return header_fail(r, line, "duplicate property", tok, len);
    if (fl_vec_push(&el->props, &prop, 1))
        return fl_fail(r->err, FL_ERR_NOMEM, r->name, line, "out of memory");
    return FL_OK;
}

/* Checks that we found what we need: vertex x, y, z and, when there are faces, indices. */
static fl_status ply_header_complete(ply_reader *r)
{
    if (!r->have_format) return header_fail(r, 2, "missing 'format' line in the header", NULL, 0);
    const ply_element *els = r->elements.data;
    int have_vertex = 0;
    for (size_t i = 0; i < r->elements.count; i++) {
        const ply_property *props = els[i].props.data;
        int roles = 0;
        for (size_t k = 0; k < els[i].props.count; k++)
            roles |= 1 << props[k].role;
        if (els[i].kind == KIND_VERTEX) {
            have_vertex = 1;
            for (int c = ROLE_X; c <= ROLE_Z; c++)
                if (!(roles & (1 << c)))
                    return fl_fail(r->err, FL_ERR_INPUT, r->name, els[i].line,
                                   "the vertex element has no scalar property '%c'",
                                   "xyz"[c - ROLE_X]);
        }
        if (els[i].kind == KIND_FACE && els[i].count > 0 && !(roles & (1 << ROLE_INDICES)))
            return fl_fail(r->err, FL_ERR_INPUT, r->name, els[i].line,
                           "the face element has no list property 'vertex_indices'");
    }
    if (!have_vertex)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line - 1,
                       "the header declares no 'element vertex'");
    return FL_OK;
}

static fl_status ply_header(ply_reader *r)
{
    const char *b, *e, *tok;
    size_t len;
    long line;
    fl_scan_init(&r->s, (const char *)r->data, r->size);
    if (r->size == 0) return header_fail(r, 1, "empty file", NULL, 0);
    if (!fl_scan_line(&r->s, &b, &e, &line) || !fl_token_is(b, (size_t)(e - b), "ply"))
        return header_fail(r, 1, "not a PLY file: the first line must be 'ply'", NULL, 0);
    for (;;) {
        if (!fl_scan_line(&r->s, &b, &e, &line))
            return header_fail(r, r->s.line, "unexpected end of file: no 'end_header'", NULL, 0);
        if (!fl_token_next(&b, e, &tok, &len)) continue;
        fl_status st = FL_OK;
        if (fl_token_is(tok, len, "format"))
            st = ply_format_line(r, b, e, line);
        else if (fl_token_is(tok, len, "element"))
            st = ply_element_line(r, b, e, line);
        else if (fl_token_is(tok, len, "property"))
            st = ply_property_line(r, b, e, line);
        else if (fl_token_is(tok, len, "end_header"))
            break;
        else if (!fl_token_is(tok, len, "comment") && !fl_token_is(tok, len, "obj_info"))
            st = header_fail(r, line, "unknown header keyword", tok, len);
        if (st) return st;
    }
    r->body = (size_t)(r->s.p - (const char *)r->data);
    return ply_header_complete(r);
}

/* The least number of bytes an item of el takes: binary, every scalar and list count at its
 * size (lists empty); ascii, one character and one separator a value. */
static uint64_t ply_min_item_size(const ply_reader *r, const ply_element *el)
{
    const ply_property *props = el->props.data;
    uint64_t n = 0;
    for (size_t k = 0; k < el->props.count; k++)
        n += r->format == PLY_ASCII
                 ? 2
                 : ply_types[props[k].is_list ? props[k].count_type : props[k].type].size;
    return n;
}

static fl_status ply_check_counts(ply_reader *r)
{
    uint64_t need = 0, have = r->size - r->body;
    if (r->format == PLY_ASCII) have++; /* the last value needs no separator */
    const ply_element *els = r->elements.data;
    for (size_t i = 0; i < r->elements.count; i++) {
        uint64_t item = ply_min_item_size(r, &els[i]);
        int overflow = item && els[i].count > (UINT64_MAX - need) / item;
        if (!overflow) need += els[i].count * item;
        if (overflow || need > have) {
            const char *fmt = "element '%s' claims %" PRIu64 " items, more than the %" PRIu64
                              " bytes after the header can hold";
            if (r->format == PLY_ASCII)
                return fl_fail(r->err, FL_ERR_INPUT, r->name, els[i].line, fmt, els[i].name,
                               els[i].count, have - 1);
            return fl_fail_at_offset(r->err, FL_ERR_INPUT, r->name, (long long)r->body, fmt,
                                     els[i].name, els[i].count, have);
        }
        if (els[i].kind == KIND_VERTEX) fl_mesh_build_reserve(&r->mb, (size_t)els[i].count, 0);
        if (els[i].kind == KIND_FACE) fl_mesh_build_reserve(&r->mb, 0, (size_t)els[i].count);
    }
    return FL_OK;
}

/* ---- binary body ---- */

/* Loads of a fixed width in either byte order. Fixed widths let the compiler turn each into
 * one load (and a byte swap for the foreign order) instead of a loop. */
static uint64_t load_bits(const unsigned char *p, int bytes, int big)
{
    uint64_t u = 0;
    if (big)
        for (int i = 0; i < bytes; i++)
            u = u << 8 | p[i];
    else
        for (int i = bytes - 1; i >= 0; i--)
            u = u << 8 | p[i];
    return u;
}

static uint16_t load16(const unsigned char *p, int big)
{
    return (uint16_t)load_bits(p, 2, big);
}
static uint32_t load32(const unsigned char *p, int big)
{
    return (uint32_t)load_bits(p, 4, big);
}
static uint64_t load64(const unsigned char *p, int big)
{
    return load_bits(p, 8, big);
}

static double load_value(const unsigned char *p, ply_type t, int big)
{
    switch (t) {
    case PLY_INT8:
        return (int8_t)p[0];
    case PLY_UINT8:
        return p[0];
    case PLY_INT16:
        return (int16_t)load16(p, big);
    case PLY_UINT16:
        return load16(p, big);
    case PLY_INT32:
        return (int32_t)load32(p, big);
    case PLY_UINT32:
        return load32(p, big);
    case PLY_FLOAT32: {
        uint32_t w = load32(p, big);
        float f;
        memcpy(&f, &w, sizeof f);
        return f;
    }
    case PLY_FLOAT64: {
        uint64_t u = load64(p, big);
        double d;
        memcpy(&d, &u, sizeof d);
        return d;
    }
    }
    return 0;
}

/* Integer types only (the header guarantees it for counts and indices). */
static long long load_integer(const unsigned char *p, ply_type t, int big)
{
    return (long long)load_value(p, t, big);
}

/* Where a body reader is: the element, the item, and (binary only) the byte offset. */
typedef struct ply_cursor {
    size_t pos;
    const ply_element *el;
    uint64_t item;
} ply_cursor;

static fl_status binary_truncated(ply_reader *r, const ply_cursor *c)
{
    return fl_fail_at_offset(r->err, FL_ERR_INPUT, r->name, (long long)c->pos,
                             "unexpected end of file in element '%s' (item %" PRIu64 " of %" PRIu64
                             ")",
                             c->el->name, c->item + 1, c->el->count);
}

/* The n indices of a face at c->pos, fan-triangulated. */
static fl_status binary_face(ply_reader *r, ply_cursor *c, long long n, ply_type t, int big)
{
    size_t size = ply_types[t].size;
    uint32_t first = 0, prev = 0;
    for (long long k = 0; k < n; k++, c->pos += size) {
        long long v = load_integer(r->data + c->pos, t, big);
        if (v < 0 || (uint64_t)v >= r->vertices)
            return fl_fail_at_offset(r->err, FL_ERR_INPUT, r->name, (long long)c->pos,
                                     "face %" PRIu64 ": vertex index %lld is out of range (the "
                                     "file has %" PRIu64 " vertices)",
                                     c->item, v, r->vertices);
        if (k == 0) first = (uint32_t)v;
        if (k >= 2) {
            fl_status st = fl_mesh_build_triangle(&r->mb, first, prev, (uint32_t)v);
            if (st)
                return fl_fail_at_offset(r->err, st, r->name, (long long)c->pos, "%s",
                                         fl_mesh_build_why(st));
        }
        prev = (uint32_t)v;
    }
    return FL_OK;
}

static fl_status binary_list(ply_reader *r, ply_cursor *c, const ply_property *p, int big)
{
    size_t csize = ply_types[p->count_type].size, isize = ply_types[p->type].size;
    if (r->size - c->pos < csize) return binary_truncated(r, c);
    long long n = load_integer(r->data + c->pos, p->count_type, big);
    if (p->role == ROLE_INDICES && n < 3)
        return fl_fail_at_offset(r->err, FL_ERR_INPUT, r->name, (long long)c->pos,
                                 "face %" PRIu64 " has %lld vertices; a face needs at least 3",
                                 c->item, n);
    if (n < 0)
        return fl_fail_at_offset(r->err, FL_ERR_INPUT, r->name, (long long)c->pos,
                                 "negative list length %lld", n);
    c->pos += csize;
    if ((uint64_t)n > (r->size - c->pos) / isize) return binary_truncated(r, c);
    if (p->role == ROLE_INDICES) return binary_face(r, c, n, p->type, big);
    c->pos += (size_t)n * isize;
    return FL_OK;
}

static fl_status binary_item(ply_reader *r, ply_cursor *c, int big)
{
    const ply_property *props = c->el->props.data;
    double xyz[3] = {0, 0, 0};
    for (size_t k = 0; k < c->el->props.count; k++) {
        const ply_property *p = &props[k];
        if (p->is_list) {
            fl_status st = binary_list(r, c, p, big);
            if (st) return st;
            continue;
        }
        size_t size = ply_types[p->type].size;
        if (r->size - c->pos < size) return binary_truncated(r, c);
        if (p->role >= ROLE_X && p->role <= ROLE_Z) {
            double v = load_value(r->data + c->pos, p->type, big);
            if (!isfinite(v))
                return fl_fail_at_offset(r->err, FL_ERR_INPUT, r->name, (long long)c->pos,
                                         "vertex %" PRIu64 ": coordinate %c is not finite", c->item,
                                         "xyz"[p->role - ROLE_X]);
            xyz[p->role - ROLE_X] = v;
        }
        c->pos += size;
    }
    if (c->el->kind != KIND_VERTEX) return FL_OK;
    fl_status st = fl_mesh_build_vertex(&r->mb, xyz[0], xyz[1], xyz[2]);
    return st ? fl_fail_at_offset(r->err, st, r->name, (long long)c->pos, "%s",
                                  fl_mesh_build_why(st))
              : FL_OK;
}

static fl_status ply_binary_body(ply_reader *r)
{
    int big = r->format == PLY_BINARY_BE;
    ply_cursor c = {.pos = r->body};
    const ply_element *els = r->elements.data;
    for (size_t i = 0; i < r->elements.count; i++) {
        c.el = &els[i];
        /* An element without properties holds no data: its items take no bytes and no
         * tokens, so do not count through them (fuzz_read_points: 5.6e17 of them hung). */
        if (els[i].props.count == 0) continue;
        for (c.item = 0; c.item < els[i].count; c.item++) {
            fl_status st = binary_item(r, &c, big);
            if (st) return st;
        }
    }
    if (c.pos != r->size)
        return fl_fail_at_offset(r->err, FL_ERR_INPUT, r->name, (long long)c.pos,
                                 "%zu bytes of unexpected data after the last element",
                                 r->size - c.pos);
    return FL_OK;
}

/* ---- ascii body ---- */

static fl_status ascii_value(ply_reader *r, const ply_cursor *c, double *v)
{
    const char *tok;
    size_t len;
    char q[64];
    if (!fl_scan_token(&r->s, 0, &tok, &len))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line,
                       "unexpected end of file in element '%s' (item %" PRIu64 " of %" PRIu64 ")",
                       c->el->name, c->item + 1, c->el->count);
    if (fl_parse_double(tok, len, v))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line,
                       "expected a number in element '%s', got %s", c->el->name,
                       fl_token_quote(tok, len, q, sizeof q));
    if (!isfinite(*v))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line, "%s is not a finite number",
                       fl_token_quote(tok, len, q, sizeof q));
    return FL_OK;
}

/* An ascii value that must be an integer of the property's integer type. */
static fl_status ascii_integer(ply_reader *r, const ply_cursor *c, long long *n)
{
    double v;
    fl_status st = ascii_value(r, c, &v);
    if (st) return st;
    if (v != floor(v) || fabs(v) > 9007199254740992.0)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line,
                       "expected an integer in element '%s', got %.17g", c->el->name, v);
    *n = (long long)v;
    return FL_OK;
}

static fl_status ascii_list(ply_reader *r, const ply_cursor *c, const ply_property *p)
{
    long long n = 0, v = 0;
    fl_status st = ascii_integer(r, c, &n);
    if (st) return st;
    if (p->role == ROLE_INDICES && n < 3)
        return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line,
                       "face %" PRIu64 " has %lld vertices; a face needs at least 3", c->item, n);
    if (n < 0) return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line, "negative list length");
    uint32_t first = 0, prev = 0;
    for (long long k = 0; k < n; k++) {
        if (p->role != ROLE_INDICES) {
            double skipped;
            if ((st = ascii_value(r, c, &skipped))) return st;
            continue;
        }
        if ((st = ascii_integer(r, c, &v))) return st;
        if (v < 0 || (uint64_t)v >= r->vertices)
            return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line,
                           "face %" PRIu64 ": vertex index %lld is out of range (the file has "
                           "%" PRIu64 " vertices)",
                           c->item, v, r->vertices);
        if (k == 0) first = (uint32_t)v;
        if (k >= 2 && (st = fl_mesh_build_triangle(&r->mb, first, prev, (uint32_t)v)))
            return fl_fail(r->err, st, r->name, r->s.line, "%s", fl_mesh_build_why(st));
        prev = (uint32_t)v;
    }
    return FL_OK;
}

static fl_status ascii_item(ply_reader *r, const ply_cursor *c)
{
    const ply_property *props = c->el->props.data;
    double xyz[3] = {0, 0, 0}, v = 0;
    for (size_t k = 0; k < c->el->props.count; k++) {
        fl_status st = props[k].is_list ? ascii_list(r, c, &props[k]) : ascii_value(r, c, &v);
        if (st) return st;
        if (props[k].role >= ROLE_X && props[k].role <= ROLE_Z) xyz[props[k].role - ROLE_X] = v;
    }
    if (c->el->kind != KIND_VERTEX) return FL_OK;
    fl_status st = fl_mesh_build_vertex(&r->mb, xyz[0], xyz[1], xyz[2]);
    return st ? fl_fail(r->err, st, r->name, r->s.line, "%s", fl_mesh_build_why(st)) : FL_OK;
}

static fl_status ply_ascii_body(ply_reader *r)
{
    ply_cursor c = {0}; /* ascii positions are tracked by r->s */
    const ply_element *els = r->elements.data;
    for (size_t i = 0; i < r->elements.count; i++) {
        c.el = &els[i];
        /* An element without properties holds no data: its items take no bytes and no
         * tokens, so do not count through them (fuzz_read_points: 5.6e17 of them hung). */
        if (els[i].props.count == 0) continue;
        for (c.item = 0; c.item < els[i].count; c.item++) {
            fl_status st = ascii_item(r, &c);
            if (st) return st;
        }
    }
    const char *tok;
    size_t len;
    char q[64];
    if (fl_scan_token(&r->s, 0, &tok, &len))
        return fl_fail(r->err, FL_ERR_INPUT, r->name, r->s.line,
                       "unexpected data %s after the last element",
                       fl_token_quote(tok, len, q, sizeof q));
    return FL_OK;
}

/* ---- entry points ---- */

fl_status fl_ply_parse(const char *name, const char *data, size_t size, fl_mesh *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    ply_reader r = {.name = name, .data = (const unsigned char *)data, .size = size, .err = err};
    fl_vec_init(&r.elements, sizeof(ply_element));
    fl_mesh_build_init(&r.mb);
    fl_status st = ply_header(&r);
    if (!st) st = ply_check_counts(&r);
    if (!st) st = r.format == PLY_ASCII ? ply_ascii_body(&r) : ply_binary_body(&r);
    ply_element *els = r.elements.data;
    for (size_t i = 0; i < r.elements.count; i++)
        fl_vec_free(&els[i].props);
    fl_vec_free(&r.elements);
    if (st) {
        fl_mesh_build_free(&r.mb);
        return st;
    }
    fl_mesh_build_finish(&r.mb, out);
    return FL_OK;
}

static void store_le(unsigned char *p, uint64_t u, size_t size)
{
    for (size_t i = 0; i < size; i++)
        p[i] = (unsigned char)(u >> (8 * i));
}

/* Binary little endian with float64 coordinates, so every double survives exactly. */
fl_status fl_ply_write(FILE *fp, const fl_mesh *mesh)
{
    fprintf(fp,
            "ply\nformat binary_little_endian 1.0\ncomment written by flintstone\n"
            "element vertex %zu\nproperty double x\nproperty double y\nproperty double z\n"
            "element face %zu\nproperty list uchar uint vertex_indices\nend_header\n",
            mesh->vertex_count, mesh->triangle_count);
    for (size_t i = 0; i < mesh->vertex_count; i++) {
        unsigned char rec[24];
        for (int c = 0; c < 3; c++) {
            uint64_t u;
            memcpy(&u, &mesh->xyz[3 * i + (size_t)c], sizeof u);
            store_le(rec + 8 * c, u, 8);
        }
        fwrite(rec, 1, sizeof rec, fp);
    }
    for (size_t i = 0; i < mesh->triangle_count; i++) {
        unsigned char rec[13] = {3};
        for (int k = 0; k < 3; k++)
            store_le(rec + 1 + 4 * k, mesh->tri[3 * i + (size_t)k], 4);
        fwrite(rec, 1, sizeof rec, fp);
    }
    return ferror(fp) ? FL_ERR_IO : FL_OK;
}

/* Shared pieces of the mesh readers (ply.c, stl.c, off.c, obj.c): a text scanner that counts
 * lines and never reads past the end of the buffer (buffers from fl_parse_mesh need not be
 * NUL-terminated), number parsing on such tokens, and a growable triangle mesh. */
#ifndef FL_IO_MESH_READ_H
#define FL_IO_MESH_READ_H

#include "core/core.h"

/* A cursor over text: `p` is the next unread byte, `line` its 1-based line number. */
typedef struct fl_scan {
    const char *p;
    const char *end;
    long line;
} fl_scan;

void fl_scan_init(fl_scan *s, const char *data, size_t size);

/* The next whitespace-separated token, crossing line breaks; when `comment` is not 0 the text
 * from that character to the end of its line is skipped. Returns 0 at the end of the buffer;
 * otherwise sets tok/len and leaves s->line at the token's line. */
int fl_scan_token(fl_scan *s, char comment, const char **tok, size_t *len);

/* The next line without its terminator ("\n" or "\r\n") in [*b, *e); *line is its number.
 * Returns 0 at the end of the buffer. */
int fl_scan_line(fl_scan *s, const char **b, const char **e, long *line);

/* Skips to the start of the next line. */
void fl_scan_skip_line(fl_scan *s);

/* The next token in [*p, e) without crossing lines; advances *p past it. Returns 0 if none. */
int fl_token_next(const char **p, const char *e, const char **tok, size_t *len);

/* 1 if the token equals the NUL-terminated word (case-sensitive / ASCII case-insensitive). */
int fl_token_is(const char *tok, size_t len, const char *word);
int fl_token_is_nocase(const char *tok, size_t len, const char *word);

/* Parses the whole token as a double (strtod syntax, so "nan" and "inf" parse and the caller
 * rejects them). Returns 0 on success, -1 if the token is not a number. */
int fl_parse_double(const char *tok, size_t len, double *v);

/* Parses the whole token as a decimal integer with optional sign. Returns 0 on success, -1 if
 * it is not an integer or does not fit in long long. */
int fl_parse_integer(const char *tok, size_t len, long long *v);

/* Formats a token for an error message ("'abc'", truncated when long). */
const char *fl_token_quote(const char *tok, size_t len, char *buf, size_t size);

/* A triangle mesh under construction. Indices are uint32_t, so neither count may exceed
 * UINT32_MAX; adding beyond that returns FL_ERR_INPUT, an allocation failure FL_ERR_NOMEM. */
typedef struct fl_mesh_build {
    fl_vec xyz; /* doubles, 3 per vertex */
    fl_vec tri; /* uint32_t, 3 per triangle */
} fl_mesh_build;

void fl_mesh_build_init(fl_mesh_build *b);
/* Reserves room (a hint: failure is ignored, the arrays still grow on demand). */
void fl_mesh_build_reserve(fl_mesh_build *b, size_t vertices, size_t triangles);
/* Inline: called once per vertex and triangle of files with millions of them. */
static inline fl_status fl_mesh_build_vertex(fl_mesh_build *b, double x, double y, double z)
{
    if (b->xyz.count / 3 >= UINT32_MAX) return FL_ERR_INPUT;
    if (b->xyz.count + 3 > b->xyz.capacity && fl_vec_reserve(&b->xyz, b->xyz.count + 3))
        return FL_ERR_NOMEM;
    double *d = (double *)b->xyz.data + b->xyz.count;
    d[0] = x;
    d[1] = y;
    d[2] = z;
    b->xyz.count += 3;
    return FL_OK;
}

static inline fl_status fl_mesh_build_triangle(fl_mesh_build *b, uint32_t a, uint32_t c, uint32_t d)
{
    if (b->tri.count / 3 >= UINT32_MAX) return FL_ERR_INPUT;
    if (b->tri.count + 3 > b->tri.capacity && fl_vec_reserve(&b->tri, b->tri.count + 3))
        return FL_ERR_NOMEM;
    uint32_t *t = (uint32_t *)b->tri.data + b->tri.count;
    t[0] = a;
    t[1] = c;
    t[2] = d;
    b->tri.count += 3;
    return FL_OK;
}

static inline size_t fl_mesh_build_vertex_count(const fl_mesh_build *b)
{
    return b->xyz.count / 3;
}
/* A message for a status returned by the functions above. */
const char *fl_mesh_build_why(fl_status status);
/* Moves the arrays into *out (which must not own memory) and empties b. */
void fl_mesh_build_finish(fl_mesh_build *b, fl_mesh *out);
void fl_mesh_build_free(fl_mesh_build *b);

/* Reads "x y z" from the tokens of one text line [p, e) (further tokens are left alone) and adds
 * the vertex. `what` names the element in messages ("'v'", "a vertex"); errors name the file
 * and line: too few coordinates, a token that is not a number, NaN or infinity. */
fl_status fl_mesh_build_text_vertex(fl_mesh_build *b, const char *p, const char *e,
                                    const char *what, const char *name, long line, fl_error *err);

#endif /* FL_IO_MESH_READ_H */

/* Shared pieces of the mesh readers: bounded text scanning, number parsing, mesh building. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/mesh_read.h"
#include "io/text_scan.h"

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

void fl_scan_init(fl_scan *s, const char *data, size_t size)
{
    s->p = data;
    s->end = data + size;
    s->line = 1;
}

int fl_scan_token(fl_scan *s, char comment, const char **tok, size_t *len)
{
    const char *p = s->p, *e = s->end;
    for (;;) {
        while (p < e && is_space(*p)) {
            if (*p == '\n') s->line++;
            p++;
        }
        if (p == e) {
            s->p = p;
            return 0;
        }
        if (comment && *p == comment) {
            const char *nl = memchr(p, '\n', (size_t)(e - p));
            p = nl ? nl : e;
            continue;
        }
        break;
    }
    const char *b = p;
    while (p < e && !is_space(*p) && !(comment && *p == comment))
        p++;
    *tok = b;
    *len = (size_t)(p - b);
    s->p = p;
    return 1;
}

int fl_scan_line(fl_scan *s, const char **b, const char **e, long *line)
{
    if (s->p >= s->end) return 0;
    const char *nl = memchr(s->p, '\n', (size_t)(s->end - s->p));
    const char *stop = nl ? nl : s->end;
    *b = s->p;
    *e = stop;
    if (*e > *b && (*e)[-1] == '\r') (*e)--;
    *line = s->line;
    if (nl) {
        s->p = nl + 1;
        s->line++;
    } else {
        s->p = s->end;
    }
    return 1;
}

void fl_scan_skip_line(fl_scan *s)
{
    const char *b, *e;
    long line;
    fl_scan_line(s, &b, &e, &line);
}

int fl_token_next(const char **p, const char *e, const char **tok, size_t *len)
{
    const char *q = *p;
    while (q < e && is_space(*q))
        q++;
    if (q == e) {
        *p = q;
        return 0;
    }
    const char *b = q;
    while (q < e && !is_space(*q))
        q++;
    *tok = b;
    *len = (size_t)(q - b);
    *p = q;
    return 1;
}

int fl_token_is(const char *tok, size_t len, const char *word)
{
    return strlen(word) == len && memcmp(tok, word, len) == 0;
}

static char lower(char c)
{
    return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c;
}

int fl_token_is_nocase(const char *tok, size_t len, const char *word)
{
    if (strlen(word) != len) return 0;
    for (size_t i = 0; i < len; i++)
        if (lower(tok[i]) != lower(word[i])) return 0;
    return 1;
}

int fl_parse_double(const char *tok, size_t len, double *v)
{
    /* One number parser for every text format (Clinger's fast path, then strtod). A NaN, an
     * infinity or an overflow like 1e999 parses as NaN, which the readers reject with their
     * location. */
    switch (fl_scan_double(tok, len, v)) {
    case FL_NUMBER_OK:
        return 0;
    case FL_NUMBER_NONFINITE:
        *v = NAN;
        return 0;
    default:
        return -1;
    }
}

int fl_parse_integer(const char *tok, size_t len, long long *v)
{
    size_t i = 0;
    int negative = 0;
    if (i < len && (tok[i] == '+' || tok[i] == '-')) negative = tok[i++] == '-';
    if (i == len) return -1;
    unsigned long long m = 0;
    const unsigned long long limit = negative ? (unsigned long long)LLONG_MAX + 1 : LLONG_MAX;
    for (; i < len; i++) {
        if (tok[i] < '0' || tok[i] > '9') return -1;
        unsigned d = (unsigned)(tok[i] - '0');
        if (m > (limit - d) / 10) return -1;
        m = m * 10 + d;
    }
    *v = negative ? (m == (unsigned long long)LLONG_MAX + 1 ? LLONG_MIN : -(long long)m)
                  : (long long)m;
    return 0;
}

const char *fl_token_quote(const char *tok, size_t len, char *buf, size_t size)
{
    /* Bytes that would garble a terminal (binary data read as text) are shown as '?'. */
    char shown[48];
    size_t n = len > 40 ? 40 : len;
    for (size_t i = 0; i < n; i++)
        shown[i] = tok[i] >= 0x20 && tok[i] < 0x7f ? tok[i] : '?';
    snprintf(buf, size, "'%.*s%s'", (int)n, shown, len > 40 ? "..." : "");
    return buf;
}

void fl_mesh_build_init(fl_mesh_build *b)
{
    fl_vec_init(&b->xyz, sizeof(double));
    fl_vec_init(&b->tri, sizeof(uint32_t));
}

void fl_mesh_build_reserve(fl_mesh_build *b, size_t vertices, size_t triangles)
{
    if (vertices <= SIZE_MAX / 3) (void)fl_vec_reserve(&b->xyz, vertices * 3);
    if (triangles <= SIZE_MAX / 3) (void)fl_vec_reserve(&b->tri, triangles * 3);
}

const char *fl_mesh_build_why(fl_status status)
{
    return status == FL_ERR_NOMEM ? "out of memory"
                                  : "too large: more than 4294967295 vertices or triangles";
}

void fl_mesh_build_finish(fl_mesh_build *b, fl_mesh *out)
{
    out->vertex_count = b->xyz.count / 3;
    out->triangle_count = b->tri.count / 3;
    out->xyz = fl_vec_release(&b->xyz);
    out->tri = fl_vec_release(&b->tri);
}

void fl_mesh_build_free(fl_mesh_build *b)
{
    fl_vec_free(&b->xyz);
    fl_vec_free(&b->tri);
}

fl_status fl_mesh_build_text_vertex(fl_mesh_build *b, const char *p, const char *e,
                                    const char *what, const char *name, long line, fl_error *err)
{
    double v[3];
    char q[64];
    for (int k = 0; k < 3; k++) {
        const char *tok;
        size_t len;
        if (!fl_token_next(&p, e, &tok, &len))
            return fl_fail(err, FL_ERR_INPUT, name, line,
                           "%s needs 3 coordinates, this line has %d", what, k);
        if (fl_parse_double(tok, len, &v[k]))
            return fl_fail(err, FL_ERR_INPUT, name, line, "expected a coordinate, got %s",
                           fl_token_quote(tok, len, q, sizeof q));
        if (!isfinite(v[k]))
            return fl_fail(err, FL_ERR_INPUT, name, line, "coordinate %s is not a finite number",
                           fl_token_quote(tok, len, q, sizeof q));
    }
    fl_status st = fl_mesh_build_vertex(b, v[0], v[1], v[2]);
    return st ? fl_fail(err, st, name, line, "%s", fl_mesh_build_why(st)) : FL_OK;
}

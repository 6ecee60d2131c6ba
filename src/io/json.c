/* Recursive-descent JSON reader (RFC 8259 grammar). Values are appended to one node array as
 * they are met, so a parent is created before its children and the root is node 0; children
 * are linked by index (not pointer) because the array moves when it grows. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/json.h"
#include "io/text_scan.h"

typedef struct parser {
    const char *name;
    const char *p, *end;
    long line;
    fl_vec nodes;   /* fl_json_node */
    fl_vec strings; /* char: decoded strings, each followed by a NUL */
    fl_error *err;
} parser;

static fl_status fail_at(parser *ps, long line, const char *fmt, ...) FL_PRINTF(3, 4);

static fl_status fail_at(parser *ps, long line, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return fl_fail(ps->err, FL_ERR_INPUT, ps->name, line, "%s", msg);
}

static fl_status out_of_memory(parser *ps)
{
    return fl_fail(ps->err, FL_ERR_NOMEM, ps->name, ps->line, "out of memory reading JSON");
}

/* The character at the cursor, for messages: 'x', "byte 0x07" or "end of file". */
static const char *describe(const parser *ps, char *buf, size_t size)
{
    if (ps->p >= ps->end) return "end of file";
    unsigned char c = (unsigned char)*ps->p;
    if (c >= 0x20 && c < 0x7f)
        snprintf(buf, size, "'%c'", c);
    else
        snprintf(buf, size, "byte 0x%02x", c);
    return buf;
}

static fl_json_node *node_at(parser *ps, size_t i)
{
    return (fl_json_node *)ps->nodes.data + i;
}

static fl_status new_node(parser *ps, fl_json_type type, size_t *index)
{
    fl_json_node n;
    memset(&n, 0, sizeof n);
    n.type = type;
    n.line = ps->line;
    n.next = FL_JSON_NONE;
    if (type == FL_JSON_ARRAY || type == FL_JSON_OBJECT) n.u.children.first = FL_JSON_NONE;
    if (fl_vec_push(&ps->nodes, &n, 1)) return out_of_memory(ps);
    *index = ps->nodes.count - 1;
    return FL_OK;
}

/* Appends child to parent's children; *last is the previous child or FL_JSON_NONE. */
static void link_child(parser *ps, size_t parent, size_t *last, size_t child)
{
    if (*last == FL_JSON_NONE)
        node_at(ps, parent)->u.children.first = child;
    else
        node_at(ps, *last)->next = child;
    node_at(ps, parent)->u.children.count++;
    *last = child;
}

static void skip_ws(parser *ps)
{
    for (; ps->p < ps->end; ps->p++) {
        char c = *ps->p;
        if (c == '\n')
            ps->line++;
        else if (c != ' ' && c != '\t' && c != '\r')
            break;
    }
}

static int hex4(const char *p, const char *end, unsigned *value)
{
    if (end - p < 4) return 0;
    unsigned v = 0;
    for (int i = 0; i < 4; i++) {
        char c = p[i];
        unsigned d;
        if (c >= '0' && c <= '9')
            d = (unsigned)(c - '0');
        else if (c >= 'a' && c <= 'f')
            d = (unsigned)(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F')
            d = (unsigned)(c - 'A' + 10);
        else
            return 0;
        v = v * 16 + d;
    }
    *value = v;
    return 1;
}

static int push_utf8(fl_vec *s, unsigned cp)
{
    char b[4];
    size_t n;
    if (cp < 0x80) {
        b[0] = (char)cp;
        n = 1;
    } else if (cp < 0x800) {
        b[0] = (char)(0xC0 | (cp >> 6));
        b[1] = (char)(0x80 | (cp & 0x3F));
        n = 2;
    } else if (cp < 0x10000) {
        b[0] = (char)(0xE0 | (cp >> 12));
        b[1] = (char)(0x80 | ((cp >> 6) & 0x3F));
        b[2] = (char)(0x80 | (cp & 0x3F));
        n = 3;
    } else {
        b[0] = (char)(0xF0 | (cp >> 18));
        b[1] = (char)(0x80 | ((cp >> 12) & 0x3F));
        b[2] = (char)(0x80 | ((cp >> 6) & 0x3F));
        b[3] = (char)(0x80 | (cp & 0x3F));
        n = 4;
    }
    return fl_vec_push(s, b, n);
}

/* \uXXXX at p (after the backslash-u): a UTF-16 unit, or a surrogate pair written as two
 * escapes. RFC 8259 §8.2 leaves lone surrogates undefined; they become U+FFFD. */
static fl_status unicode_escape(parser *ps, unsigned *cp)
{
    unsigned u;
    if (!hex4(ps->p, ps->end, &u))
        return fail_at(ps, ps->line, "\\u must be followed by 4 hexadecimal digits");
    ps->p += 4;
    unsigned lo;
    if (u >= 0xD800 && u < 0xDC00 && ps->end - ps->p >= 6 && ps->p[0] == '\\' && ps->p[1] == 'u' &&
        hex4(ps->p + 2, ps->end, &lo) && lo >= 0xDC00 && lo < 0xE000) {
        ps->p += 6;
        *cp = 0x10000 + ((u - 0xD800) << 10) + (lo - 0xDC00);
    } else {
        *cp = (u >= 0xD800 && u < 0xE000) ? 0xFFFD : u;
    }
    return FL_OK;
}

/* One escape sequence; the cursor is on the character after the backslash. */
static fl_status escape(parser *ps, long start_line)
{
    if (ps->p >= ps->end)
        return fail_at(ps, start_line, "unterminated string (it starts at line %ld)", start_line);
    static const char from[] = "\"\\/bfnrt";
    static const char to[] = "\"\\/\b\f\n\r\t";
    char c = *ps->p++;
    const char *hit = c ? strchr(from, c) : NULL;
    int bad;
    if (hit) {
        bad = fl_vec_push(&ps->strings, &to[hit - from], 1);
    } else if (c == 'u') {
        unsigned cp = 0;
        fl_status st = unicode_escape(ps, &cp);
        if (st != FL_OK) return st;
        bad = push_utf8(&ps->strings, cp);
    } else {
        char q[16];
        fl_scan_quote(&c, 1, q, sizeof q);
        return fail_at(ps, ps->line, "invalid escape '\\%s' in a string", q);
    }
    return bad ? out_of_memory(ps) : FL_OK;
}

/* A string at the cursor ('"'), decoded into the pool at *off, *len bytes plus a NUL. */
static fl_status parse_string(parser *ps, size_t *off, size_t *len)
{
    long start_line = ps->line;
    ps->p++;
    *off = ps->strings.count;
    for (;;) {
        const char *run = ps->p;
        while (ps->p < ps->end && *ps->p != '"' && *ps->p != '\\' && (unsigned char)*ps->p >= 0x20)
            ps->p++;
        if (ps->p > run && fl_vec_push(&ps->strings, run, (size_t)(ps->p - run)))
            return out_of_memory(ps);
        if (ps->p >= ps->end)
            return fail_at(ps, start_line, "unterminated string (it starts at line %ld)",
                           start_line);
        char c = *ps->p++;
        if (c == '"') break;
        if (c != '\\')
            return fail_at(ps, ps->line,
                           "control character (byte 0x%02x) inside a string; write a line "
                           "break as \\n",
                           (unsigned char)c);
        fl_status st = escape(ps, start_line);
        if (st != FL_OK) return st;
    }
    *len = ps->strings.count - *off;
    return fl_vec_push(&ps->strings, "", 1) ? out_of_memory(ps) : FL_OK;
}

static const char *skip_digits(const char *p, const char *end)
{
    while (p < end && *p >= '0' && *p <= '9')
        p++;
    return p;
}

/* A number per RFC 8259 §6: -? (0 | [1-9][0-9]*) (.[0-9]+)? ([eE][+-]?[0-9]+)? */
static fl_status parse_number(parser *ps, size_t *index)
{
    const char *s = ps->p, *p = ps->p, *end = ps->end, *d;
    if (*p == '-') p++;
    if (p < end && *p == '0')
        p++;
    else if ((d = skip_digits(p, end)) > p)
        p = d;
    else
        return fail_at(ps, ps->line, "invalid number: a digit must follow '-'");
    if (p < end && *p == '.') {
        if ((d = skip_digits(p + 1, end)) == p + 1)
            return fail_at(ps, ps->line, "invalid number: a digit must follow '.'");
        p = d;
    }
    if (p < end && (*p == 'e' || *p == 'E')) {
        p++;
        if (p < end && (*p == '+' || *p == '-')) p++;
        if ((d = skip_digits(p, end)) == p)
            return fail_at(ps, ps->line, "invalid number: the exponent has no digits");
        p = d;
    }
    double v;
    fl_number_scan scan = fl_scan_double(s, (size_t)(p - s), &v);
    /* 1e999 is valid JSON; it becomes an infinity that the user of the value may refuse
     * (a coordinate) or ignore (a property). */
    if (scan == FL_NUMBER_NONFINITE) v = *s == '-' ? -HUGE_VAL : HUGE_VAL;
    if (scan == FL_NUMBER_INVALID) {
        char q[40];
        fl_scan_quote(s, (size_t)(p - s), q, sizeof q);
        return fail_at(ps, ps->line, "number %s is too long", q);
    }
    ps->p = p;
    fl_status st = new_node(ps, FL_JSON_NUMBER, index);
    if (st == FL_OK) node_at(ps, *index)->u.number = v;
    return st;
}

static fl_status parse_value(parser *ps, int depth, size_t *index);

/* After an element: ',' (then another element) or the closing bracket. Returns 1 when the
 * container continues, 0 when it closed, -1 on error (err filled). */
static int after_element(parser *ps, char close, const char *what, long start_line)
{
    char buf[16];
    skip_ws(ps);
    if (ps->p < ps->end && *ps->p == close) {
        ps->p++;
        return 0;
    }
    if (ps->p < ps->end && *ps->p == ',') {
        ps->p++;
        skip_ws(ps);
        if (ps->p < ps->end && *ps->p == close) {
            fail_at(ps, ps->line, "trailing comma before '%c'", close);
            return -1;
        }
        return 1;
    }
    if (ps->p >= ps->end)
        fail_at(ps, ps->line, "unexpected end of file inside the %s that starts at line %ld", what,
                start_line);
    else
        fail_at(ps, ps->line, "expected ',' or '%c' after %s element, found %s", close,
                close == ']' ? "an array" : "an object", describe(ps, buf, sizeof buf));
    return -1;
}

static fl_status parse_array(parser *ps, int depth, size_t *index)
{
    long start_line = ps->line;
    fl_status st = new_node(ps, FL_JSON_ARRAY, index);
    if (st != FL_OK) return st;
    ps->p++;
    skip_ws(ps);
    if (ps->p < ps->end && *ps->p == ']') {
        ps->p++;
        return FL_OK;
    }
    size_t last = FL_JSON_NONE;
    for (;;) {
        size_t child = 0;
        if ((st = parse_value(ps, depth + 1, &child)) != FL_OK) return st;
        link_child(ps, *index, &last, child);
        int more = after_element(ps, ']', "array", start_line);
        if (more <= 0) return more < 0 ? FL_ERR_INPUT : FL_OK;
    }
}

static fl_status parse_member(parser *ps, int depth, size_t *child)
{
    char buf[16];
    if (ps->p >= ps->end || *ps->p != '"')
        return fail_at(ps, ps->line, "expected a member name in double quotes, found %s",
                       describe(ps, buf, sizeof buf));
    size_t key_off, key_len;
    fl_status st = parse_string(ps, &key_off, &key_len);
    if (st != FL_OK) return st;
    skip_ws(ps);
    if (ps->p >= ps->end || *ps->p != ':')
        return fail_at(ps, ps->line, "expected ':' after a member name, found %s",
                       describe(ps, buf, sizeof buf));
    ps->p++;
    if ((st = parse_value(ps, depth + 1, child)) != FL_OK) return st;
    node_at(ps, *child)->key_off = key_off;
    node_at(ps, *child)->key_len = key_len;
    return FL_OK;
}

static fl_status parse_object(parser *ps, int depth, size_t *index)
{
    long start_line = ps->line;
    fl_status st = new_node(ps, FL_JSON_OBJECT, index);
    if (st != FL_OK) return st;
    ps->p++;
    skip_ws(ps);
    if (ps->p < ps->end && *ps->p == '}') {
        ps->p++;
        return FL_OK;
    }
    size_t last = FL_JSON_NONE;
    for (;;) {
        size_t child = 0;
        if ((st = parse_member(ps, depth, &child)) != FL_OK) return st;
        link_child(ps, *index, &last, child);
        int more = after_element(ps, '}', "object", start_line);
        if (more <= 0) return more < 0 ? FL_ERR_INPUT : FL_OK;
    }
}

static fl_status parse_literal(parser *ps, size_t *index)
{
    static const struct {
        const char *text;
        fl_json_type type;
    } literals[] = {{"true", FL_JSON_TRUE}, {"false", FL_JSON_FALSE}, {"null", FL_JSON_NULL}};
    for (size_t i = 0; i < 3; i++) {
        size_t n = strlen(literals[i].text);
        if ((size_t)(ps->end - ps->p) >= n && memcmp(ps->p, literals[i].text, n) == 0) {
            ps->p += n;
            return new_node(ps, literals[i].type, index);
        }
    }
    char q[40];
    fl_scan_quote(ps->p, (size_t)(ps->end - ps->p) < 8 ? (size_t)(ps->end - ps->p) : 8, q,
                  sizeof q);
    return fail_at(ps, ps->line, "unexpected '%s', expected a value", q);
}

static fl_status parse_value(parser *ps, int depth, size_t *index)
{
    char buf[16];
    skip_ws(ps);
    if (ps->p >= ps->end) return fail_at(ps, ps->line, "unexpected end of file, expected a value");
    char c = *ps->p;
    if ((c == '[' || c == '{') && depth >= FL_JSON_MAX_DEPTH)
        return fail_at(ps, ps->line, "arrays and objects nested deeper than %d levels",
                       FL_JSON_MAX_DEPTH);
    if (c == '[') return parse_array(ps, depth, index);
    if (c == '{') return parse_object(ps, depth, index);
    if (c == '"') {
        fl_status st = new_node(ps, FL_JSON_STRING, index);
        size_t off = 0, len = 0;
        if (st == FL_OK) st = parse_string(ps, &off, &len);
        if (st == FL_OK) {
            node_at(ps, *index)->u.string.off = off;
            node_at(ps, *index)->u.string.len = len;
        }
        return st;
    }
    if (c == '-' || (c >= '0' && c <= '9')) return parse_number(ps, index);
    if (c == 't' || c == 'f' || c == 'n') return parse_literal(ps, index);
    return fail_at(ps, ps->line, "unexpected %s, expected a value", describe(ps, buf, sizeof buf));
}

fl_status fl_json_parse(const char *name, const char *data, size_t size, fl_json_doc *doc,
                        fl_error *err)
{
    memset(doc, 0, sizeof *doc);
    parser ps = {.name = name, .p = data, .end = data + size, .line = 1, .err = err};
    fl_vec_init(&ps.nodes, sizeof(fl_json_node));
    fl_vec_init(&ps.strings, 1);
    if (size >= 3 && memcmp(data, "\xEF\xBB\xBF", 3) == 0) ps.p += 3; /* RFC 8259 §8.1 */
    size_t root = 0;
    fl_status st = parse_value(&ps, 0, &root);
    if (st == FL_OK) {
        skip_ws(&ps);
        char buf[16];
        if (ps.p < ps.end)
            st = fail_at(&ps, ps.line, "extra data after the JSON value: %s",
                         describe(&ps, buf, sizeof buf));
    }
    if (st != FL_OK) {
        fl_vec_free(&ps.nodes);
        fl_vec_free(&ps.strings);
        return st;
    }
    doc->node_count = ps.nodes.count;
    doc->nodes = fl_vec_release(&ps.nodes);
    doc->strings = fl_vec_release(&ps.strings);
    return FL_OK;
}

void fl_json_free(fl_json_doc *doc)
{
    free(doc->nodes);
    free(doc->strings);
    memset(doc, 0, sizeof *doc);
}

size_t fl_json_member(const fl_json_doc *doc, size_t object, const char *key)
{
    const fl_json_node *o = &doc->nodes[object];
    if (o->type != FL_JSON_OBJECT) return FL_JSON_NONE;
    size_t n = strlen(key);
    for (size_t c = o->u.children.first; c != FL_JSON_NONE; c = doc->nodes[c].next) {
        const fl_json_node *m = &doc->nodes[c];
        if (m->key_len == n && memcmp(doc->strings + m->key_off, key, n) == 0) return c;
    }
    return FL_JSON_NONE;
}

int fl_json_is_string(const fl_json_doc *doc, size_t node, const char *s)
{
    if (node == FL_JSON_NONE) return 0;
    const fl_json_node *n = &doc->nodes[node];
    size_t len = strlen(s);
    return n->type == FL_JSON_STRING && n->u.string.len == len &&
           memcmp(doc->strings + n->u.string.off, s, len) == 0;
}

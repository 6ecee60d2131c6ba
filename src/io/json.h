/* A small strict JSON reader (RFC 8259) for GeoJSON: the whole text becomes a tree of nodes
 * in one array, linked by index. Strings are decoded (escapes, \u surrogate pairs to UTF-8)
 * into one pool. Nesting is limited to FL_JSON_MAX_DEPTH so hostile input ("[[[[...") cannot
 * exhaust the stack; every error names the line. */
#ifndef FL_IO_JSON_H
#define FL_IO_JSON_H

#include <stddef.h>

#include "core/core.h"

#define FL_JSON_MAX_DEPTH 64
#define FL_JSON_NONE ((size_t)-1)

typedef enum fl_json_type {
    FL_JSON_NULL,
    FL_JSON_FALSE,
    FL_JSON_TRUE,
    FL_JSON_NUMBER,
    FL_JSON_STRING,
    FL_JSON_ARRAY,
    FL_JSON_OBJECT
} fl_json_type;

typedef struct fl_json_node {
    fl_json_type type;
    long line;      /* where the value starts, 1-based */
    size_t next;    /* next element or member of the same parent, or FL_JSON_NONE */
    size_t key_off; /* object members: the member name in the string pool */
    size_t key_len;
    union {
        double number; /* FL_JSON_NUMBER: +-HUGE_VAL beyond the double range */
        struct {
            size_t off, len;
        } string; /* FL_JSON_STRING: in the string pool */
        struct {
            size_t first, count;
        } children; /* FL_JSON_ARRAY, FL_JSON_OBJECT */
    } u;
} fl_json_node;

/* The root value is nodes[0]. */
typedef struct fl_json_doc {
    fl_json_node *nodes;
    size_t node_count;
    char *strings;
} fl_json_doc;

/* Parses data[0..size) (need not be NUL-terminated) into doc; on failure doc is empty and err
 * names `name` and the line. Duplicate member names are kept; lookups find the first. */
fl_status fl_json_parse(const char *name, const char *data, size_t size, fl_json_doc *doc,
                        fl_error *err);
void fl_json_free(fl_json_doc *doc);

/* The first member of object node `object` named `key`, or FL_JSON_NONE. */
size_t fl_json_member(const fl_json_doc *doc, size_t object, const char *key);

/* Whether node is a string equal to s. */
int fl_json_is_string(const fl_json_doc *doc, size_t node, const char *s);

#endif /* FL_IO_JSON_H */

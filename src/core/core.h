/* Internal helpers shared by every module: error reporting, checked allocation, growable
 * arrays and atomic output files. Not part of the public API. */
#ifndef FL_CORE_H
#define FL_CORE_H

#include <stdarg.h>
#include <stdio.h>
#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

#if defined(__GNUC__)
#define FL_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define FL_PRINTF(f, a)
#endif

/* Fills err (if not NULL) and returns status, so callers can write
 * `return fl_fail(err, FL_ERR_INPUT, path, line, "expected 3 numbers, got %d", n);`.
 * `file` may be NULL; `line` < 0 means unknown. */
fl_status fl_fail(fl_error *err, fl_status status, const char *file, long line, const char *fmt,
                  ...) FL_PRINTF(5, 6);

/* Same for binary files: the location is a byte offset. */
fl_status fl_fail_at_offset(fl_error *err, fl_status status, const char *file, long long offset,
                            const char *fmt, ...) FL_PRINTF(5, 6);

/* Resets err to "no error". */
void fl_error_clear(fl_error *err);

/* malloc(n * size) that returns NULL on overflow instead of wrapping. */
void *fl_alloc_array(size_t n, size_t size);
void *fl_calloc_array(size_t n, size_t size);
/* realloc(p, n * size) with the same overflow check; on failure p is untouched. */
void *fl_realloc_array(void *p, size_t n, size_t size);

/* A growable array of fixed-size elements (amortised doubling). */
typedef struct fl_vec {
    void *data;
    size_t count;    /* elements in use */
    size_t capacity; /* elements allocated */
    size_t elem;     /* bytes per element */
} fl_vec;

void fl_vec_init(fl_vec *v, size_t elem);
/* Makes room for at least `count` elements; 0 on success, -1 on allocation failure. */
int fl_vec_reserve(fl_vec *v, size_t count);
/* Appends n elements copied from src (src may be NULL to append zeroed elements). */
int fl_vec_push(fl_vec *v, const void *src, size_t n);
void fl_vec_free(fl_vec *v);
/* Hands the buffer to the caller (shrunk to fit when possible) and empties v. */
void *fl_vec_release(fl_vec *v);

/* Output files are written to "<path>.tmp.<pid>" next to the target and renamed over it only
 * when complete, so a failure never leaves a half-written file. */
typedef struct fl_out_file {
    FILE *fp;
    char path[1024];
    char tmp_path[1100];
} fl_out_file;

fl_status fl_out_open(fl_out_file *out, const char *path, int binary, fl_error *err);
/* Flushes, closes and renames; on any failure removes the temporary and reports FL_ERR_IO. */
fl_status fl_out_commit(fl_out_file *out, fl_error *err);
/* Closes and removes the temporary; the target is untouched. */
void fl_out_abort(fl_out_file *out);

/* Lower-cased extension of path without the dot ("" if none), written into ext[size]. */
void fl_path_extension(const char *path, char *ext, size_t size);

/* Union-find over uint32_t elements stored in `parent` (parent[x] == x for a root), with path
 * halving; a union makes the smaller root the root, so every set's root is its smallest
 * element and results do not depend on the order of unions. */
static inline uint32_t fl_uf_find(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

static inline void fl_uf_union(uint32_t *parent, uint32_t a, uint32_t b)
{
    a = fl_uf_find(parent, a);
    b = fl_uf_find(parent, b);
    if (a < b)
        parent[b] = a;
    else if (b < a)
        parent[a] = b;
}

/* Reports progress; returns nonzero when the caller asked to stop. Safe with fn == NULL. */
static inline int fl_progress(fl_progress_fn fn, void *user, const char *stage, double fraction)
{
    return fn ? fn(user, stage, fraction) : 0;
}

#endif /* FL_CORE_H */

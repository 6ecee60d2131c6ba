/* The closest-point evaluation (docs/sweep.md, "Against CGAL's AABB tree"), shared by ours
 * (bench/eval_closest.c) and the CGAL peer (bench/peers/cgal_aabb.cpp): both read the same
 * binary mesh and query files, made once by `eval_closest prepare`. C11 and C++17.
 *   PREFIX.mesh     uint64 V, uint64 T, V*3 doubles, T*3 uint32
 *   PREFIX.KIND.q   raw doubles, 3 a query point
 *   PREFIX.KIND.NAME.d  the distances a method found, one double a query */
#ifndef FL_BENCH_CLOSEST_EVAL_H
#define FL_BENCH_CLOSEST_EVAL_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef struct ce_mesh {
    uint64_t v, t;
    double *xyz;
    uint32_t *tri;
} ce_mesh;

static double ce_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int ce_read_mesh(const char *prefix, ce_mesh *m)
{
    char path[1024];
    snprintf(path, sizeof path, "%s.mesh", prefix);
    FILE *f = fopen(path, "rb");
    if (!f) return 1;
    int ok = fread(&m->v, 8, 1, f) == 1 && fread(&m->t, 8, 1, f) == 1;
    m->xyz = ok ? (double *)malloc(m->v * 3 * sizeof(double)) : NULL;
    m->tri = ok ? (uint32_t *)malloc(m->t * 3 * sizeof(uint32_t)) : NULL;
    ok = ok && fread(m->xyz, sizeof(double), m->v * 3, f) == m->v * 3 &&
         fread(m->tri, sizeof(uint32_t), m->t * 3, f) == m->t * 3;
    fclose(f);
    return !ok;
}

/* Reads PREFIX.KIND.q; returns the queries (3 doubles each) and their count in *n. */
static double *ce_read_queries(const char *prefix, const char *kind, size_t *n)
{
    char path[1024];
    snprintf(path, sizeof path, "%s.%s.q", prefix, kind);
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long bytes = ftell(f);
    fseek(f, 0, SEEK_SET);
    *n = (size_t)bytes / (3 * sizeof(double));
    double *q = (double *)malloc(*n * 3 * sizeof(double) + 1);
    if (fread(q, 3 * sizeof(double), *n, f) != *n) {
        free(q);
        q = NULL;
    }
    fclose(f);
    return q;
}

static void ce_write_distances(const char *prefix, const char *kind, const char *name,
                               const double *d, size_t n)
{
    char path[1024];
    snprintf(path, sizeof path, "%s.%s.%s.d", prefix, kind, name);
    FILE *f = fopen(path, "wb");
    if (!f) return;
    fwrite(d, sizeof(double), n, f);
    fclose(f);
}

#endif

/* The 2D boundary-construction evaluation (docs/reconstruct2d.md, "Evaluation on country
 * borders"), shared by our program and the peers so that every method gets the same inputs and
 * is scored by the same code. Compiles as C11 and C++17.
 *
 * Input: a .xy file of rings (one ring a block, blank lines between; countries-50m.xy from npm
 * world-atlas, made by bench/get-data.sh). Each ring with at least `min_points` distinct points
 * becomes one case: its vertices, shuffled (same seed for every method), are the scattered
 * points; the ring itself is the truth. A method returns the undirected edges of the boundary it
 * found (indices into the shuffled points). Scores per case:
 *   recall     fraction of the ring's edges among the method's boundary edges
 *   precision  fraction of the method's boundary edges that are ring edges
 *   on_boundary fraction of the points that are endpoints of a boundary edge
 *   polygon    1 when the edges form one simple cycle through every point (a polygon through
 *              all points: every point has degree 2 and the edges are connected)
 *   exact      1 when the method's edges are exactly the ring's
 * The program prints, per method, one line:
 *   RESULT method=<m> cases=<n> seconds=<total time of the method's calls> recall=<mean>
 *          precision=<mean> on_boundary=<mean> polygon=<fraction> exact=<fraction>
 * Given an output directory, each program also writes every method's edges to
 * <dir>/<method>.edges (r2_edges_open / r2_edges_write), so that one scorer
 * (bench/tools/recon2_symdiff.c) measures the area of every method's result against the true
 * ring with the same code. Format, per case in load order: a line "case <k> <m>", then m lines
 * "<a> <b>" (indices into the case's shuffled points). */
#ifndef FL_BENCH_RECON2_EVAL_H
#define FL_BENCH_RECON2_EVAL_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct r2_case {
    size_t n;
    double *xy;      /* shuffled points, 2 a point */
    uint32_t *truth; /* truth[i] = position in the ring of shuffled point i */
} r2_case;

typedef struct r2_set {
    size_t count;
    r2_case *cases;
} r2_set;

static inline int r2_cmp_xy(const void *a, const void *b)
{
    const double *p = (const double *)a, *q = (const double *)b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    if (p[1] != q[1]) return p[1] < q[1] ? -1 : 1;
    return 0;
}

/* Adds a ring if it has min_points points, all distinct (rings with repeated points are
 * skipped: their truth is not a simple polygon through distinct points), and not collinear. */
static inline void r2_add_ring(r2_set *s, const double *ring, size_t n, size_t min_points,
                        uint64_t *seed)
{
    if (n > 1 && ring[0] == ring[2 * (n - 1)] && ring[1] == ring[2 * (n - 1) + 1]) n--;
    if (n < min_points) return;
    double *sorted = (double *)malloc(n * 2 * sizeof(double));
    memcpy(sorted, ring, n * 2 * sizeof(double));
    qsort(sorted, n, 2 * sizeof(double), r2_cmp_xy);
    int distinct = 1;
    for (size_t i = 1; i < n && distinct; i++)
        if (r2_cmp_xy(sorted + 2 * (i - 1), sorted + 2 * i) == 0) distinct = 0;
    free(sorted);
    if (!distinct) return;
    /* Rings along one line (Antarctica's cut at -90 degrees) bound nothing: skip them. */
    int flat = 1;
    for (size_t i = 2; i < n && flat; i++)
        flat = (ring[2] - ring[0]) * (ring[2 * i + 1] - ring[1]) ==
               (ring[3] - ring[1]) * (ring[2 * i] - ring[0]);
    if (flat) return;
    r2_case c;
    c.n = n;
    c.xy = (double *)malloc(n * 2 * sizeof(double));
    c.truth = (uint32_t *)malloc(n * sizeof(uint32_t));
    uint32_t *perm = (uint32_t *)malloc(n * sizeof(uint32_t));
    for (size_t i = 0; i < n; i++) perm[i] = (uint32_t)i;
    for (size_t i = n - 1; i > 0; i--) { /* Fisher-Yates with a fixed xorshift seed */
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        size_t j = (size_t)(*seed % (i + 1));
        uint32_t t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    for (size_t i = 0; i < n; i++) {
        c.xy[2 * i] = ring[2 * perm[i]];
        c.xy[2 * i + 1] = ring[2 * perm[i] + 1];
        c.truth[i] = perm[i];
    }
    free(perm);
    s->cases = (r2_case *)realloc(s->cases, (s->count + 1) * sizeof(r2_case));
    s->cases[s->count++] = c;
}

/* Reads the rings of path; returns 0 on success. */
static inline int r2_load(const char *path, size_t min_points, r2_set *s)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "cannot open %s\n", path);
        return 1;
    }
    s->count = 0;
    s->cases = NULL;
    size_t cap = 1024, n = 0;
    double *ring = (double *)malloc(cap * 2 * sizeof(double));
    uint64_t seed = 0x9e3779b97f4a7c15ull;
    char line[256];
    while (fgets(line, sizeof line, f)) {
        double x, y;
        if (line[0] == '#') continue;
        if (sscanf(line, "%lf %lf", &x, &y) == 2) {
            if (n == cap) ring = (double *)realloc(ring, (cap *= 2) * 2 * sizeof(double));
            ring[2 * n] = x;
            ring[2 * n + 1] = y;
            n++;
        } else if (n) {
            r2_add_ring(s, ring, n, min_points, &seed);
            n = 0;
        }
    }
    if (n) r2_add_ring(s, ring, n, min_points, &seed);
    free(ring);
    fclose(f);
    return 0;
}

static inline void r2_free(r2_set *s)
{
    for (size_t i = 0; i < s->count; i++) {
        free(s->cases[i].xy);
        free(s->cases[i].truth);
    }
    free(s->cases);
}

typedef struct r2_score {
    size_t cases;
    double seconds, recall, precision, on_boundary, polygon, exact;
} r2_score;

static inline size_t r2_find(size_t *parent, size_t x)
{
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

/* Scores one case: `edges` holds m undirected edges (2 indices each) of the method's boundary. */
static inline void r2_score_case(r2_score *sc, const r2_case *c, const uint32_t *edges,
                                 size_t m)
{
    size_t n = c->n, hits = 0, touched = 0;
    size_t *degree = (size_t *)calloc(n, sizeof(size_t));
    size_t *parent = (size_t *)malloc(n * sizeof(size_t));
    for (size_t i = 0; i < n; i++) parent[i] = i;
    for (size_t e = 0; e < m; e++) {
        uint32_t a = edges[2 * e], b = edges[2 * e + 1];
        degree[a]++;
        degree[b]++;
        parent[r2_find(parent, a)] = r2_find(parent, b);
        uint32_t d = c->truth[a] > c->truth[b] ? c->truth[a] - c->truth[b]
                                               : c->truth[b] - c->truth[a];
        if (d == 1 || d == n - 1) hits++;
    }
    int cycle = m == n;
    for (size_t i = 0; i < n; i++) {
        if (degree[i]) touched++;
        if (degree[i] != 2 || r2_find(parent, i) != r2_find(parent, 0)) cycle = 0;
    }
    sc->cases++;
    sc->recall += (double)hits / (double)n;
    sc->precision += m ? (double)hits / (double)m : 0;
    sc->on_boundary += (double)touched / (double)n;
    sc->polygon += cycle;
    sc->exact += hits == n && m == n;
    free(degree);
    free(parent);
}

static inline void r2_print(const r2_score *sc, const char *method)
{
    double k = sc->cases ? (double)sc->cases : 1;
    printf("RESULT method=%s cases=%zu seconds=%.6f recall=%.4f precision=%.4f on_boundary=%.4f "
           "polygon=%.4f exact=%.4f\n",
           method, sc->cases, sc->seconds, sc->recall / k, sc->precision / k, sc->on_boundary / k,
           sc->polygon / k, sc->exact / k);
}

/* <dir>/<method>.edges for writing, or NULL when dir is NULL, empty or "-". */
static inline FILE *r2_edges_open(const char *dir, const char *method)
{
    if (!dir || !dir[0] || (dir[0] == '-' && !dir[1])) return NULL;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.edges", dir, method);
    FILE *f = fopen(path, "w");
    if (!f) fprintf(stderr, "cannot write %s\n", path);
    return f;
}

static inline void r2_edges_write(FILE *f, size_t k, const uint32_t *edges, size_t m)
{
    if (!f) return;
    fprintf(f, "case %zu %zu\n", k, m);
    for (size_t e = 0; e < m; e++) fprintf(f, "%u %u\n", edges[2 * e], edges[2 * e + 1]);
}

#endif

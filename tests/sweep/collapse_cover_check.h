/* The bound invariant of the edge-collapse hierarchy checked by dense sampling (shared by
 * test_collapse_tables.c and test_collapse_deform.c): the test's own split walk with the
 * paper's error restoring, and the cover check (every sample point of the input within ε of
 * some present triangle, distances by the independent oracle). */
#ifndef COLLAPSE_COVER_CHECK_H
#define COLLAPSE_COVER_CHECK_H

#include "sweep/collapse_internal.h"
#include "test_collapse_meshes.h"

/* Runs split k after its dependencies (recursively: the test's own walk, chain successor
 * first), checking that each split only replaces present triangles, and restores u's and v's
 * errors (cur) as the paper's split does. */
static inline void run_split(const fl_sweep_collapse *h, uint8_t *done, double *cur, uint32_t k)
{
    if (done[k]) return;
    if (h->split[k].next != FL_COLLAPSE_NONE) run_split(h, done, cur, h->split[k].next);
    for (uint32_t t = h->new_start[k]; t < h->new_start[k + 1]; t++)
        if (h->tri[t].destroyer != FL_COLLAPSE_NONE)
            run_split(h, done, cur, h->tri[t].destroyer);
    for (uint32_t t = h->new_start[k]; t < h->new_start[k + 1]; t++)
        CHECK(fl_collapse_present(h, done, t));
    for (uint32_t i = h->old_start[k]; i < h->old_start[k + 1]; i++)
        CHECK(!fl_collapse_present(h, done, h->old[i]));
    done[k] = 1;
    cur[h->split[k].v] = h->err_parent[h->split[k].u];
    cur[h->split[k].u] = h->err_self[h->split[k].u];
    for (uint32_t i = h->old_start[k]; i < h->old_start[k + 1]; i++)
        CHECK(fl_collapse_present(h, done, h->old[i]));
}

/* How many sample points of the input (m: the mesh at the hierarchy's current positions) lie
 * farther than ε from every present triangle. */
static inline size_t cover_misses(const fl_mesh *m, const fl_sweep_collapse *h,
                                  const uint8_t *done, const double *cur)
{
    uint32_t *present = malloc(h->tri_count * sizeof *present);
    size_t np = 0, bad = 0;
    for (uint32_t t = 0; t < h->tri_count; t++)
        if (fl_collapse_present(h, done, t)) present[np++] = t;
    const int s = 4; /* a grid of barycentric samples per triangle, corners included */
    for (size_t f = 0; f < m->triangle_count; f++)
        for (int i = 0; i <= s; i++)
            for (int j = 0; i + j <= s; j++) {
                double p[3], a = (double)i / s, b = (double)j / s;
                for (int c = 0; c < 3; c++)
                    p[c] = (1 - a - b) * oracle_vertex(m->xyz, m->tri, f, 0)[c] +
                           a * oracle_vertex(m->xyz, m->tri, f, 1)[c] +
                           b * oracle_vertex(m->xyz, m->tri, f, 2)[c];
                int covered = 0;
                for (size_t x = 0; x < np && !covered; x++) {
                    const fl_collapse_tri *t = h->tri + present[x];
                    ld d = oracle_triangle(p, h->xyz + 3 * (size_t)t->v[0],
                                           h->xyz + 3 * (size_t)t->v[1],
                                           h->xyz + 3 * (size_t)t->v[2]);
                    covered = d <= fl_collapse_eps(h, cur, present[x]) + 1e-14;
                }
                bad += !covered;
            }
    free(present);
    return bad;
}

/* Every sample point of the input lies within ε of a present triangle. */
static inline void check_cover(const fl_mesh *m, const fl_sweep_collapse *h, const uint8_t *done,
                               const double *cur)
{
    size_t bad = cover_misses(m, h, done, cur);
    CHECK_MSG(bad == 0, "%zu sample points not covered by the present triangles", bad);
}

#endif /* COLLAPSE_COVER_CHECK_H */

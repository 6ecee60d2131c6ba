/* Meshsweeper's mesh hierarchy by edge collapses (Guéziec 2001, §4.2-4.3): the fixed tables
 * shared by the builder (collapse_build.c) and the selective refinement (collapse_query.c).
 *
 * Every triangle that ever exists during the simplification is one entry of `tri`: the input
 * ("fine") triangles are 0 .. fine_count-1, then the triangles made by collapse 0, collapse 1,
 * ... in order. Collapse k (a half-edge collapse u -> v, the vertex u disappears) consumes the
 * triangles incident to u (`old` list of k, Fig. 5 "triangles added by the split") and creates
 * the triangles [new_start[k], new_start[k+1]) ("triangles affected by the split": those the
 * split removes again). Split k undoes collapse k. A triangle t is in the current mesh iff the
 * split of its creator is not done and the split of its destroyer is (or it has none):
 * present = (creator == NONE || !done[creator]) && (destroyer == NONE || done[destroyer]).
 * Split k may run only when all its new triangles are present, i.e. after the splits of their
 * destroyers: the "split before" dependencies, which point to later collapses only, so they
 * form a DAG (Fig. 5).
 *
 * The bound invariant (what makes the priority process exact). Each fine triangle f is owned
 * by exactly one triangle of every valid current mesh: by f itself if present, otherwise the
 * owner chosen when the collapse that consumed its previous owner ran. `radius[t]` is at least
 * the distance of every vertex of every fine triangle owned by t to the triangle t (measured,
 * widened for rounding). The set of points within radius[t] of t is convex, so it contains
 * those fine triangles whole: d(q, t) - radius[t] is a lower bound of the distance from q to
 * every fine triangle t stands for. Every current mesh's owned sets partition the fine mesh,
 * so the smallest such bound over the current mesh is a lower bound of the distance to the
 * input (tests/sweep/test_collapse_tables.c samples it densely). */
#ifndef FL_SWEEP_COLLAPSE_INTERNAL_H
#define FL_SWEEP_COLLAPSE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

#define FL_COLLAPSE_NONE UINT32_MAX

/* One triangle of the hierarchy (32 bytes). */
typedef struct fl_collapse_tri {
    uint32_t v[3];      /* vertex indices into the input vertices (positions never move) */
    uint32_t rep;       /* a vertex of a fine triangle owned by t (upper bounds); NONE if none */
    uint32_t creator;   /* the collapse that made t; NONE for a fine triangle */
    uint32_t destroyer; /* the collapse that consumed t; NONE for a base-mesh triangle */
    double radius;      /* the bound radius of the invariant above (0 for fine triangles) */
} fl_collapse_tri;

struct fl_sweep_collapse {
    size_t vertex_count;
    double *xyz; /* copy of the input vertices */
    double scale; /* largest |coordinate|, for the rounding slack */
    size_t fine_count;
    size_t tri_count;
    fl_collapse_tri *tri;
    size_t split_count;
    uint32_t *new_start; /* split_count + 1 offsets: new triangles of collapse k */
    uint32_t *old_start; /* split_count + 1 offsets into old */
    uint32_t *old;       /* the triangles each collapse consumed */
    size_t base_count;
    uint32_t *base; /* the base mesh: triangles never consumed */
};

/* Whether triangle t is in the current mesh given the done splits (see above). */
static inline int fl_collapse_present(const fl_sweep_collapse *h, const uint8_t *done, uint32_t t)
{
    const fl_collapse_tri *x = h->tri + t;
    return (x->creator == FL_COLLAPSE_NONE || !done[x->creator]) &&
           (x->destroyer == FL_COLLAPSE_NONE || done[x->destroyer]);
}

/* Bytes held by the hierarchy (the fixed tables). */
size_t fl_collapse_bytes(const fl_sweep_collapse *h);

#endif /* FL_SWEEP_COLLAPSE_INTERNAL_H */

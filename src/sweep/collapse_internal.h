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
 * The bounds: two errors per vertex (§4.2 "vertex error"). The paper's ε of a triangle is the
 * largest sphere radius (error) at its corners. Here: every fine triangle f is owned by exactly
 * one triangle of every valid current mesh (by f itself if present, otherwise the owner chosen
 * when the collapse that consumed its previous owner ran); r(t), the largest distance of a
 * vertex of a fine triangle owned by t to t (widened for rounding), is what t's swept sphere
 * must reach. Collapse k (u -> v) raises the error of v, and only of v, to
 *     e_after = max(e_before(v), r(t) for t among k's new triangles),
 * so errors only grow along the collapse sequence. The fixed tables keep the paper's two
 * errors per vertex u: err_self[u] (u's error when it was contracted; for a base vertex, its
 * final error) and err_parent[u] (the parent's error before contracting u). A cursor keeps the
 * current error of every vertex (one double): splitting k sets cur[u] = err_self[u] and
 * cur[v] = err_parent[u]; a reset to the base mesh sets cur = err_self.
 *
 * Why ε(t) = max(cur at t's corners) bounds t's owned fine triangles (t coarse, made by
 * collapse k into v): the collapses involving v (into v, then v's own contraction) form a
 * chain, and split k also needs the next collapse of v's chain split first (`next[k]`, an
 * extra "split before" edge). So the collapses into v still in effect are a prefix of v's
 * chain and cur[v] is the error after the last of them, >= e_after of k (errors grow), >= r(t)
 * while t is present (k in effect). Hence ε(t) >= r(t); the set of points within ε(t) of t is
 * convex, contains the owned fine triangles' vertices, so contains them whole: d(q,t) - ε(t)
 * is a lower bound of the distance to every fine triangle t stands for, and the owned sets of
 * a current mesh partition the input. The same chain gives cur[u] = err_self[u] at u's split
 * (every collapse into u precedes u's own in the chain, hence is still in effect). Fine
 * triangles are exact leaves (ε = 0). tests/sweep/test_collapse_tables.c samples it densely.
 * Errors that drop when a split runs only make the kept keys of neighbour triangles
 * conservative; dirty entries pick up the smaller error when recomputed. */
#ifndef FL_SWEEP_COLLAPSE_INTERNAL_H
#define FL_SWEEP_COLLAPSE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

#define FL_COLLAPSE_NONE UINT32_MAX

/* One triangle of the hierarchy (24 bytes). */
typedef struct fl_collapse_tri {
    uint32_t v[3];      /* vertex indices (positions move only by §5.3 updates) */
    uint32_t rep;       /* a vertex of a fine triangle owned by t (upper bounds); NONE if none */
    uint32_t creator;   /* the collapse that made t; NONE for a fine triangle */
    uint32_t destroyer; /* the collapse that consumed t; NONE for a base-mesh triangle */
} fl_collapse_tri;

/* One vertex split (undoing the half-edge collapse u -> v) and its chain successor. */
typedef struct fl_collapse_split {
    uint32_t u, v;
    uint32_t next; /* the next collapse of v's chain (into v, or v's own), or NONE */
} fl_collapse_split;

struct fl_sweep_collapse {
    size_t vertex_count;
    double *xyz; /* the current vertex positions (the input's, or a §5.3 update's) */
    double scale; /* largest |coordinate| ever held, for the rounding slack */
    size_t fine_count;
    size_t tri_count;
    fl_collapse_tri *tri;
    size_t split_count;
    uint32_t *new_start; /* split_count + 1 offsets: new triangles of collapse k */
    uint32_t *old_start; /* split_count + 1 offsets into old */
    uint32_t *old;       /* the triangles each collapse consumed */
    size_t base_count;
    uint32_t *base; /* the base mesh: triangles never consumed */
    fl_collapse_split *split; /* split_count entries */
    double *err_self;   /* per vertex: its error when contracted (base vertices: final) */
    double *err_parent; /* per vertex: its parent's error before contracting it (0 if none) */
    /* §5.3 deformation (collapse_deform.c): the positions the errors were measured at and
     * those errors; NULL while xyz is still those positions (err_* then are the measured
     * errors, otherwise they are the measured ones inflated by the displacements). */
    double *xyz_ref;
    double *err_self_ref, *err_parent_ref;
    /* Every update adds its largest vertex displacement to `moved` and counts itself in
     * `updates`; a cursor catches up before its next query (collapse_query.c). */
    double moved;
    uint64_t updates;
};

/* Whether triangle t is in the current mesh given the done splits (see above). */
static inline int fl_collapse_present(const fl_sweep_collapse *h, const uint8_t *done, uint32_t t)
{
    const fl_collapse_tri *x = h->tri + t;
    return (x->creator == FL_COLLAPSE_NONE || !done[x->creator]) &&
           (x->destroyer == FL_COLLAPSE_NONE || done[x->destroyer]);
}

/* The bound radius ε of triangle t given the current vertex errors (see above). */
static inline double fl_collapse_eps(const fl_sweep_collapse *h, const double *cur, uint32_t t)
{
    if (t < h->fine_count) return 0;
    const uint32_t *v = h->tri[t].v;
    double a = cur[v[0]], b = cur[v[1]], c = cur[v[2]];
    return a > b ? (a > c ? a : c) : (b > c ? b : c);
}

/* Restores the two vertex errors split k changes (§4.3 "restore the vertex errors"). */
static inline void fl_collapse_split_errors(const fl_sweep_collapse *h, double *cur, uint32_t k)
{
    uint32_t u = h->split[k].u;
    cur[h->split[k].v] = h->err_parent[u];
    cur[u] = h->err_self[u];
}

/* A split of k's "split before" set not done yet, or NONE: the destroyers of k's new
 * triangles (each present only once its destroyer's split ran) and the next collapse of the
 * parent's chain (so that the parent's error is restored in order). */
static inline uint32_t fl_collapse_pending(const fl_sweep_collapse *h, const uint8_t *done,
                                           uint32_t k)
{
    uint32_t n = h->split[k].next;
    if (n != FL_COLLAPSE_NONE && !done[n]) return n;
    for (uint32_t t = h->new_start[k]; t < h->new_start[k + 1]; t++) {
        uint32_t d = h->tri[t].destroyer;
        if (d != FL_COLLAPSE_NONE && !done[d]) return d;
    }
    return FL_COLLAPSE_NONE;
}

/* The ownership of fine triangles while the collapse sequence runs (collapse_owners.c),
 * shared by the build and the §5.3 refit, which replays the sequence at new positions: every
 * triangle t owns the fine triangles of the list fhead[t] -> fnext[f] -> ...; rad[t] is r(t),
 * the largest distance of their vertices to t (widened for rounding). */
typedef struct fl_collapse_owners {
    const double *xyz;
    fl_collapse_tri *tri; /* the fine triangles first: tri[f].v are their vertices */
    double *rad;          /* per triangle */
    uint32_t *fhead;      /* per triangle */
    uint32_t *fnext;      /* per fine triangle */
    double scale;
} fl_collapse_owners;

/* Collapse k consumed the n_old triangles `old` and made [first, end): hands every fine
 * triangle they own to the new triangle nearest its centroid and grows that one's r(t) to
 * reach it (and its `rep`, if none yet, becomes one of its vertices). */
void fl_collapse_hand_over(fl_collapse_owners *o, const uint32_t *old, size_t n_old,
                           uint32_t first, uint32_t end);

/* Records the errors of collapse u -> v that made [first, end) (collapse_internal.h): the
 * parent's error before goes to err_parent[u]; v's error grows to reach the new triangles'
 * r(t). err[u] stays u's error when contracted. */
static inline void fl_collapse_grow_error(const double *rad, uint32_t first, uint32_t end,
                                          uint32_t u, uint32_t v, double *err,
                                          double *err_parent)
{
    double e = err[v];
    for (uint32_t t = first; t < end; t++)
        if (!(e >= rad[t])) e = rad[t];
    err_parent[u] = err[v];
    err[v] = e;
}

/* Bytes held by the hierarchy (the fixed tables). */
size_t fl_collapse_bytes(const fl_sweep_collapse *h);

#endif /* FL_SWEEP_COLLAPSE_INTERNAL_H */

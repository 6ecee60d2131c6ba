/* Internal state of 2D constriction (thesis ch. 5), shared by the files of src/reconstruct:
 * reconstruct2.c (the public entry), reconstruct2_io.c (writing results),
 * constrict2.c (Algorithm 5.1 on the Delaunay triangulation), criteria2.c (the keys),
 * heap2.c (the priority queue), flip2.c (walking and inserting segments by edge flips),
 * augment2.c (locked constriction, §5.4), keep2.c (constrained constriction, §5.7) and
 * order2.c (listing the final boundary).
 * Not part of the public API. */
#ifndef FL_CONSTRICT2_INTERNAL_H
#define FL_CONSTRICT2_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "core/core.h"

#define C2_NONE UINT32_MAX

/* A heap entry: deleting boundary edge a->b (interior on its left) with triangle a b c.
 * lazy = 1: the key is not computed yet; it is the γ-indicator of a b c, known to be at least
 * the heap's first bar (c2_gamma_at_least), so the entry is parked and its key is computed only
 * if the bar is ever raised past it (heap2.c). */
typedef struct c2_entry {
    double key;
    uint32_t a, b, c;
    uint32_t lazy; /* fills the struct's padding: still 24 bytes */
} c2_entry;

/* The priority queue (heap2.c): pops entries in key order, NaN after every number, ties by the
 * input indices of (a, b, c) (orig[], or the indices themselves when orig is NULL), so runs are
 * deterministic and do not depend on the internal numbering. Entries whose key is at least the
 * current bar are parked unsorted; only the others are in the 4-ary heap (see heap2.c). */
typedef struct c2_heap {
    c2_entry *items; /* the 4-ary heap: keys below the bar */
    size_t heaped, capacity;
    int items_lent;   /* items is the caller's memory, as parked_lent below */
    c2_entry *parked; /* keys at or above the bar, and NaN keys; unsorted */
    size_t parked_count, parked_capacity;
    int parked_lent;  /* parked is the caller's memory (c2_heap_lend): never freed here, and
                         copied into an allocation of our own when it fills up */
    size_t count; /* heaped + parked_count */
    int level;    /* the bar is c2_heap's ladder[level]; past the ladder nothing is parked */
    const uint32_t *orig;
    const double *xy; /* the points, to compute lazy entries' keys (γ-indicators) */
} c2_heap;

/* 0, or -1 when out of memory. A lazy entry is parked as it is at the first bar; its key is
 * computed (from xy) when the bar is raised, or at once when the bar has moved already. */
int c2_heap_push(c2_heap *h, c2_entry e);
/* The first bar of the ladder: keys at or above it are parked while the bar has not moved. */
double c2_heap_first_bar(void);
/* Requires count > 0. 0, or -1 when out of memory (*out unchanged): moving parked entries into
 * the heap may have to grow it. */
int c2_heap_pop(c2_heap *h, c2_entry *out);
void c2_heap_clear(c2_heap *h); /* empties it (keeps the memory and orig) */
/* Gives the empty heap `bytes` of caller memory (8-byte aligned) for its entries (an eighth for
 * the heap proper, the rest for the parked entries, which on a closed curve are a third of all
 * pushes); it must stay valid until c2_heap_free. Does nothing if the heap has memory already
 * or `bytes` is too small. */
void c2_heap_lend(c2_heap *h, void *memory, size_t bytes);
void c2_heap_free(c2_heap *h);

/* The pruned triangulation. Triangles keep the slots of the Delaunay triangulation; a deleted
 * triangle has alive[t] = 0 and its living neighbours point to C2_NONE across the shared edge,
 * so "adj == C2_NONE on a living triangle" means "boundary edge". Edge flips (augmentation and
 * kept edges) rewrite two slots in place, so the living triangles always tile the region inside
 * the current boundary. */
typedef struct c2_state {
    const double *xy;       /* n points in the internal numbering (see below) */
    size_t n, unique_count; /* internal vertices: n == unique_count */
    size_t n_input;         /* input points, duplicates included */
    /* Internal numbering: the Delaunay builder's insertion order (fl_dt2_build_ranked: BRIO
     * rounds, Hilbert order within a round), so that vertices close in the plane are close in
     * memory. Constriction runs along a front, and with the input numbering (shuffled points:
     * random) every vertex it touched was a cache miss in each per-vertex array. The builder
     * hands over its coordinate copy in that order, so the shuffled input is not gathered a
     * second time. Results are mapped back on output; ties between keys are broken by input
     * indices, so the result does not depend on the numbering. */
    uint32_t *orig;   /* n: internal -> input index (the first of its duplicates) */
    uint32_t *inv;    /* n_input: input index -> internal index; NULL unless edges are kept */
    double *xy_store; /* owned storage behind xy */
    size_t tcount;
    uint32_t *tri, *adj;
    uint8_t *alive;
    int lent;              /* alive, on_boundary and bnext live in the Delaunay builder's spare
                              memory (fl_dt2_ranked.spare, inside tri's allocation): not freed */
    int lazy_adj;          /* deletions leave the neighbours' links to the deleted triangle in
                              place (see c2_settle_adj); the rule above holds only once it is 0 */
    uint32_t *vtri;        /* per vertex: a living triangle at it; only kept up to date once
                              flips may happen (c2_keep_dt makes it), NULL before */
    uint8_t *on_boundary;  /* per vertex */
    uint32_t *bnext;       /* per boundary vertex: the next boundary vertex (counterclockwise) */
    uint32_t *btri;        /* per boundary vertex v: the living triangle with edge v->bnext[v] */
    size_t boundary_count; /* boundary vertices */
    uint32_t *keep_nb;     /* 2 per vertex: partners along kept edges, C2_NONE when unused;
                              NULL when no edge is kept (the common case skips every check) */
    fl_reconstruct2_criterion criterion;
    int augmented;   /* nonzero once edges of γ([-1,1],[c0,1]), c0 < 0, take part */
    size_t *g_start; /* augmented mode: the graph's neighbours of v are g_nb[g_start[v] ..
                        g_start[v+1]-1], sorted (Delaunay edges plus the extra edges) */
    uint32_t *g_nb;
    uint32_t *dt_copy; /* the Delaunay triangulation as built (dt_count triangles), copied by
                          c2_keep_dt before the first flip; NULL while tri is still that */
    size_t dt_count;
    c2_heap heap;
} c2_state;

static inline const double *c2_pt(const c2_state *s, uint32_t v)
{
    return s->xy + 2 * (size_t)v;
}

static inline int c2_is_kept(const c2_state *s, uint32_t p, uint32_t q)
{
    if (!s->keep_nb) return 0;
    return s->keep_nb[2 * (size_t)p] == q || s->keep_nb[2 * (size_t)p + 1] == q;
}

/* §5.7 extended to the moment a kept edge's second end joins the boundary: vertex c may join
 * through triangle a b c only if each kept partner of c already on the boundary is a or b, so
 * that the kept edge becomes a boundary edge then; otherwise it would end as a chord, which no
 * later deletion can turn into a boundary edge without dropping the points beyond it. */
static inline int c2_keep_allows(const c2_state *s, uint32_t a, uint32_t b, uint32_t c)
{
    if (!s->keep_nb) return 1;
    for (int j = 0; j < 2; j++) {
        uint32_t k = s->keep_nb[2 * (size_t)c + j];
        if (k != C2_NONE && k != a && k != b && s->on_boundary[k]) return 0;
    }
    return 1;
}

/* The Delaunay triangulation as built: tri itself until a flip changed it. */
static inline const uint32_t *c2_dt_tri(const c2_state *s)
{
    return s->dt_copy ? s->dt_copy : s->tri;
}

/* reconstruct2.c: prepares for flips, once: keeps a copy of the Delaunay triangulation before
 * tri is first flipped (the result returns it, augmentation reads it) and makes vtri, which
 * only the flips' walks need (plain constriction never reads it). 0, or -1 when out of
 * memory. */
int c2_keep_dt(c2_state *s);

/* Corner of triangle t holding vertex v, or -1. */
static inline int c2_corner(const c2_state *s, uint32_t t, uint32_t v)
{
    const uint32_t *c = s->tri + 3 * (size_t)t;
    return c[0] == v ? 0 : c[1] == v ? 1 : c[2] == v ? 2 : -1;
}

/* criteria2.c: the key of deleting a->b with triangle a b c (counterclockwise) under s's
 * criterion; smaller is deleted first. For the Voronoi skeleton the key depends on the living
 * neighbours of face t (pass C2_NONE when a b c is not a face yet: the γ-indicator is used). */
double c2_key(const c2_state *s, uint32_t a, uint32_t b, uint32_t c, uint32_t t);
double c2_gamma_indicator(const double *a, const double *b, const double *c);
/* 1 when c2_gamma_indicator(a, b, c) is certainly at least `bar` (0 < bar < 1) — the angle at
 * c is acute and its sine at most 1 - bar with a wide margin — decided without square roots;
 * 0 when unsure (the caller then computes the key). */
int c2_gamma_at_least(const double *a, const double *b, const double *c, double bar);

/* constrict2.c: plain constriction never follows a link from a living triangle to a deleted
 * one: the two neighbours that the deletion of face t (edge a->b on the boundary, apex c not)
 * exposes are across c-a and b-c, and a triangle across an edge at c died only if c were on the
 * boundary already. So while nothing else reads the links (no flips, no skeleton key, which
 * looks at the living neighbours), a deletion only clears alive[t] and skips the two random
 * writes into the neighbours' links (measured: most of the time of a deletion on a 1e6-point
 * curve). This clears every link to a deleted triangle once, before anything that relies on
 * "C2_NONE across a boundary edge" runs (c2_keep_dt, called before the first flip). */
void c2_settle_adj(c2_state *s);
/* constrict2.c: deletes face t whose edge a->b is on the boundary and whose third vertex is
 * not, and pushes the new boundary edges' candidates. 0, or -1 when out of memory. */
int c2_delete_face(c2_state *s, uint32_t t, uint32_t a);
/* Pushes the removable candidates of boundary edge a->bnext[a] (the face in Delaunay mode;
 * every γ-graph triangle in augmented mode). 0, or -1 when out of memory. */
int c2_push_candidates(c2_state *s, uint32_t a);

/* flip2.c: inserts segment a-b into the living triangulation by edge flips (Sloan's method)
 * unless it is an edge already. Fails (returns 0, triangulation unchanged) when the segment
 * leaves the region, passes through a vertex or crosses a kept edge; 1 on success, -1 when
 * out of memory. */
int c2_insert_segment(c2_state *s, uint32_t a, uint32_t b);
/* Restores the constrained Delaunay property around the kept edges by Lawson's flips.
 * 0, or -1 when out of memory. */
int c2_restore_delaunay(c2_state *s);

/* augment2.c: the augmented constriction (§5.4) run after constriction of the Delaunay
 * triangulation locked. Tries c0 = -k/levels, k = 1..levels, and stores the c0 that brought
 * the last point onto the boundary in *c0_used (NaN if none did). FL_OK or FL_ERR_NOMEM /
 * cancelled. */
fl_status c2_augment(c2_state *s, int levels, double *c0_used, fl_progress_fn progress,
                     void *progress_user, fl_error *err);
/* Runs Algorithm 5.1's loop (lines 3-8) until every point is on the boundary or the heap is
 * empty. FL_OK or FL_ERR_NOMEM / cancelled. */
fl_status c2_constrict(c2_state *s, fl_progress_fn progress, void *progress_user, fl_error *err);

/* augment2.c: pushes every triangle a b c of the augmented graph with c inside (a->b being
 * the boundary edge a->bnext[a]). 0, or -1 when out of memory. */
int c2_push_graph_candidates(c2_state *s, uint32_t a);

/* order2.c: fills out[0..boundary_count-1] with the boundary cycle from boundary vertex
 * `start`. 0, or -1 when out of memory. */
int c2_boundary_order(const c2_state *s, uint32_t start, uint32_t *out);

/* keep2.c: validates the kept edges (mapped to distinct points through rep[]) and inserts them
 * into the full triangulation; fills keep_nb. */
fl_status c2_keep_edges(c2_state *s, const uint32_t *rep, const uint32_t *keep, size_t count,
                        fl_error *err);

#endif /* FL_CONSTRICT2_INTERNAL_H */

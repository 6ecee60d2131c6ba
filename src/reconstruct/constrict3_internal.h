/* Internal interface of 3D constriction (constrict3*.c): the keys that order removable boundary
 * tetrahedra and the constriction state shared by the loop and the output extraction. */
#ifndef FL_CONSTRICT3_INTERNAL_H
#define FL_CONSTRICT3_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "core/core.h"

/* Corners of the face opposite corner k of a positively oriented tetrahedron, counterclockwise
 * seen from outside it (the fl_dt3 convention in include/flintstone.h). */
extern const int constrict3_face[4][3];

/* γ-indicator (thesis Def. 5.2, eq. 5.2) of triangle a, b, c with respect to vertex l: with r
 * the circumradius of a b c and R the circumradius of the tetrahedron a b c l, |γ| = 1 - r/R,
 * positive when the circumsphere's centre lies on l's side of the plane of a b c, negative on
 * the other side. In [-1, 1]; -1 for l nearly in the triangle's plane inside its circumcircle. */
double constrict3_gamma_indicator(const double *a, const double *b, const double *c,
                                  const double *l);

/* Area change of removing tetrahedron t (thesis eq. 4.1): (inner face area - boundary face
 * area) / total face area; `boundary_mask` has bit k set when the face opposite corner k is on
 * the boundary. */
double constrict3_area_change(const double *p, const uint32_t *t, unsigned boundary_mask);

/* One candidate in the heap of removable boundary tetrahedra. `version` is the tetrahedron's
 * version when it was pushed: a newer version makes the entry stale (lazy invalidation). */
typedef struct constrict3_entry {
    double key;
    uint32_t tet;
    uint32_t version;
} constrict3_entry;

/* Binary min-heap on key (ties: lower tetrahedron index, so runs are reproducible). */
typedef struct constrict3_heap {
    constrict3_entry *a;
    size_t count, cap;
} constrict3_heap;

int constrict3_heap_push(constrict3_heap *h, constrict3_entry e); /* 0, or -1 on NOMEM */
constrict3_entry constrict3_heap_pop(constrict3_heap *h);         /* count must be > 0 */
void constrict3_heap_free(constrict3_heap *h);

/* The state of constriction over a tetrahedralization: at first the Delaunay one, later changed
 * by the unlocking flips (constrict3_unlock.c), so it is a proper tetrahedralization of the
 * convex hull but no longer necessarily Delaunay. A tetrahedron is in the region while
 * removed[t] == 0; a face of a region tetrahedron is a boundary face when the neighbour across
 * it is removed or absent (convex hull). The per-tetrahedron arrays have room for `cap`. */
typedef struct constrict3_state {
    const double *p;     /* input points */
    size_t n;            /* input points */
    size_t tet_count;    /* tetrahedra (slots) */
    size_t cap;          /* allocated slots */
    uint32_t *tet;       /* 4 per tetrahedron, positively oriented */
    uint32_t *adj;       /* 4 per tetrahedron, UINT32_MAX on the hull */
    uint8_t *removed;    /* per tetrahedron */
    uint8_t *keepmask;   /* per tetrahedron: bit k = the face opposite corner k is kept; NULL
                            when nothing is kept */
    uint32_t *version;   /* per tetrahedron: bumped when its boundary faces change */
    uint32_t *bfaces;    /* per point: boundary faces incident to it */
    size_t on_boundary;  /* distinct points with bfaces > 0 */
    size_t region_count; /* tetrahedra not removed */
    size_t keep_total;   /* distinct kept triangles */
    size_t keep_on;      /* of those, on the boundary now */
    fl_vec added;        /* uint32_t triples: the triangles the unlocking flips added (input
                            indices), for the augmented_c0 report */
} constrict3_state;

/* Marks the kept triangles (§5.7) in s->keepmask (allocated here) and counts those on the
 * initial boundary. rep maps every input index to its first duplicate. FL_ERR_INPUT for a bad
 * triple or one that is not a face of the triangulation; FL_ERR_NOMEM. */
fl_status constrict3_mark_kept(constrict3_state *s, const uint32_t *rep, const uint32_t *keep,
                               size_t count, fl_error *err);

/* Unlocking (§5.4) by 2-3 flips, see constrict3_unlock.c. Called when no boundary tetrahedron
 * is removable but points remain inside (max_key = INFINITY), or when constriction is stalled
 * (constrict3_chase.c; only flips whose key is below max_key): makes non-conflicting flips, each turning a region
 * tetrahedron with a boundary face into one whose opposite vertex is an inside point (so it is
 * removable), and pushes those onto the heap through push(). *flips receives how many were
 * made (0: none possible); the triangles they add are appended to s->added.
 * Returns 0, or -1 on NOMEM. */
typedef int (*constrict3_push_fn)(constrict3_state *s, void *ctx, uint32_t t);
int constrict3_unlock(constrict3_state *s, constrict3_push_fn push, void *ctx, double max_key,
                      size_t *flips);
/* *c0 = the smallest c1' (Def. 3.3) of the triangles in s->added, over the distinct points (dup
 * maps every input index to its first duplicate); NaN when there are none. 0, or -1 on NOMEM. */
int constrict3_augmented_c0(const constrict3_state *s, const uint32_t *dup, double *c0);

/* Chasing the last inside points (constrict3_chase.c): while constriction is stalled, early
 * unlocking flips that beat the heap's root, else removals only near the inside points. */
typedef struct constrict3_chase {
    size_t stall, limit; /* removals since a point last joined; stalled at `limit` */
    size_t last_on;      /* s->on_boundary after the last removal */
    int focus;           /* removals restricted to near[] */
    size_t radius;       /* face steps from a tetrahedron with an inside vertex */
    uint8_t *near;       /* per tetrahedron (the first near_count) */
    size_t near_count;
    constrict3_heap deferred; /* entries held back while focused */
} constrict3_chase;

void constrict3_chase_init(constrict3_chase *c, size_t on_boundary);
void constrict3_chase_free(constrict3_chase *c);
/* Before removing popped entry e (valid and removable) while points are inside: 0 = remove it,
 * 1 = it was deferred or flips were made (pop again), -1 = NOMEM. Flips are added to *flips. */
int constrict3_chase_before(constrict3_state *s, constrict3_chase *c, constrict3_heap *h,
                            constrict3_entry e, constrict3_push_fn push, void *ctx,
                            size_t *flips);
/* The heap ran empty: while focused with entries deferred, doubles the radius and returns them
 * to the heap (1); 0 when there is nothing to widen; -1 on NOMEM. */
int constrict3_chase_widen(constrict3_state *s, constrict3_chase *c, constrict3_heap *h);
/* After a removal: a new boundary point ends the stall and the focus. 0, or -1 on NOMEM. */
int constrict3_chase_after(const constrict3_state *s, constrict3_chase *c, constrict3_heap *h);

/* 1 when face k of region tetrahedron t is on the boundary. */
static inline int constrict3_face_is_boundary(const constrict3_state *s, uint32_t t, int k)
{
    uint32_t nb = s->adj[4 * (size_t)t + k];
    return nb == UINT32_MAX || s->removed[nb];
}

/* Fills out's tri, tet, inside, counts and volume from the final state; 0 or -1 on NOMEM. */
int constrict3_extract(const constrict3_state *s, const uint32_t *duplicate_of, size_t n,
                       fl_reconstruction3 *out);

/* Debug builds: 1 when the current boundary is closed, manifold, oriented and of genus 0
 * (checked with fl_mesh_check). */
int constrict3_boundary_is_sphere(const constrict3_state *s, size_t n);

#endif /* FL_CONSTRICT3_INTERNAL_H */

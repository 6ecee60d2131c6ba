/* Internal interface of the 3D Delaunay and regular triangulations (dt3_*.c, rt3.c).
 *
 * The triangulation is kept as a flat tetrahedron store: tetrahedron t has vertices
 * dt3_v(m, t)[0..3] and links dt3_n(m, t)[0..3], where link k = (u << 2) | j means that the face
 * opposite corner k of t is the face opposite corner j of u. Every tetrahedron is positively
 * oriented in Shewchuk's convention, fl_orient3d(v0, v1, v2, v3) > 0. The convex hull is closed
 * by "infinite" tetrahedra that have the vertex DT3_INF in one corner, so every tetrahedron has
 * exactly four neighbours. An infinite tetrahedron is positively oriented when replacing DT3_INF
 * by any point strictly outside its hull face gives a positive finite tetrahedron. */
#ifndef FL_DT3_INTERNAL_H
#define FL_DT3_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "core/core.h"

#define DT3_INF UINT32_MAX        /* the infinite vertex */
#define DT3_DEAD (UINT32_MAX - 1) /* first corner of a tetrahedron on the free list */
#define DT3_NONE UINT32_MAX       /* no tetrahedron */
/* Neighbour links pack a tetrahedron index and a corner into 32 bits. */
#define DT3_MAX_TETS (((size_t)1 << 30) - 1) /* so that no link equals DT3_NONE */

/* Corners of the face opposite corner k, ordered so that the face is counterclockwise seen from
 * outside the tetrahedron (an even permutation of the tetrahedron with k last). */
extern const int dt3_face_corners[4][3];

typedef struct dt3_mesh {
    const double *pts;   /* point coordinates in local (insertion) numbering, `stride` apart */
    int stride;          /* 3 for points, 4 for weighted points (x, y, z, w) */
    int weighted;        /* power test instead of in-sphere test */
    const uint32_t *gid; /* local index -> caller's index: the perturbation priority */
    uint32_t *cell;      /* 8 per tetrahedron slot: 4 corners, then 4 links (one cache line
                            for half a pair of tetrahedra: a face test reads both) */
    uint8_t *mark;       /* per slot, 0 between insertions */
    size_t slots, cap;   /* slots in use (live or free), slots allocated */
    uint32_t free_head;  /* free list chained through the first link */
    uint32_t last;       /* a live tetrahedron: where the next walk starts */
    uint64_t rng;        /* xorshift state for the stochastic walk */
    fl_vec cavity;       /* uint32 tetrahedra in conflict */
    fl_vec touched;      /* uint32 tetrahedra tested and found not in conflict */
    fl_vec boundary;     /* uint32 (t << 2 | k): cavity faces seen from inside */
    fl_vec created;      /* uint32 tetrahedra created by the current insertion */
    uint32_t *vstamp;    /* weighted only: per point, to find vertices the cavity swallowed */
} dt3_mesh;

static inline uint32_t *dt3_v(const dt3_mesh *m, size_t t)
{
    return m->cell + 8 * t;
}
static inline uint32_t *dt3_n(const dt3_mesh *m, size_t t)
{
    return m->cell + 8 * t + 4;
}

/* Result of inserting one point. */
typedef enum dt3_insert_result { DT3_INSERTED, DT3_REDUNDANT, DT3_NOMEM } dt3_insert_result;

/* Sets up the store with the first tetrahedron v[0..3] (local indices of four points that are
 * not coplanar, any orientation) and its four infinite neighbours. 0 or -1 (no memory). */
int dt3_mesh_init(dt3_mesh *m, const uint32_t v[4], size_t expected_points);
void dt3_mesh_free(dt3_mesh *m);

/* Inserts local point p (Bowyer-Watson). In the weighted case, a point whose lifted point lies
 * above the lower hull is not inserted (DT3_REDUNDANT), and vertices that the new point hides
 * are appended to *hidden (uint32 local indices). */
dt3_insert_result dt3_insert(dt3_mesh *m, uint32_t p, fl_vec *hidden);

/* Is the tetrahedron slot t infinite / live? */
static inline int dt3_is_infinite(const dt3_mesh *m, uint32_t t)
{
    const uint32_t *v = dt3_v(m, t);
    return v[0] == DT3_INF || v[1] == DT3_INF || v[2] == DT3_INF || v[3] == DT3_INF;
}

/* Is e in conflict with the positively oriented tetrahedron a, b, c, d: inside its circumsphere,
 * or (weighted) is e's lifted point (p, |p|^2 - w) below the hyperplane of the lifted corners?
 * +1 yes, -1 no; never 0. ga..ge are the caller's indices.
 *
 * Ties are broken by the predicates' perturbation of the lifting (fl_insphere_sos: the point
 * with the higher index is infinitesimally heavier), never of the coordinates. That is a tiny
 * weighting of the exact points, so the result is a regular triangulation of the exact points:
 * no flat tetrahedron ever appears, and a point on a face shared by two tetrahedra gets the same
 * answer from both (their lifted hyperplanes agree on the lifted face), which keeps every
 * Bowyer-Watson cavity star-shaped on grids and cospherical input. Orientations stay unperturbed
 * (fl_orient3d), as that family of predicates requires. */
static inline int dt3_power_sos(int weighted, const double *a, const double *b, const double *c,
                                const double *d, const double *e, uint32_t ga, uint32_t gb,
                                uint32_t gc, uint32_t gd, uint32_t ge)
{
    return weighted ? fl_insphere_weighted_sos(a, b, c, d, e, ga, gb, gc, gd, ge)
                    : fl_insphere_sos(a, b, c, d, e, ga, gb, gc, gd, ge);
}

/* What dt3_build produces; dt3.c and rt3.c move it into their public structs. */
typedef struct dt3_output {
    uint32_t *duplicate_of; /* n entries */
    fl_vec hidden;          /* uint32 caller indices of hidden balls, ascending */
    size_t vertex_count;
    size_t tet_count;
    uint32_t *tet, *adj;
    size_t hull_face_count;
    uint32_t *hull_faces;
    double *centers; /* circumcentres (3 per tetrahedron) or orthogonal balls (4), or NULL */
} dt3_output;

/* The whole pipeline for n points (stride 3) or balls (stride 4): validation, merging of
 * duplicates, BRIO order, first tetrahedron, insertion, extraction. */
fl_status dt3_build(const double *in, size_t n, int weighted, fl_progress_fn progress, void *user,
                    int want_centers, dt3_output *out, fl_error *err);
void dt3_output_free(dt3_output *out);

/* Checks a triangulation (see fl_dt3_verify / fl_rt3_verify). `kept[i]` is nonzero for the
 * points that must be vertices. */
fl_status dt3_verify(const double *in, size_t n, int weighted, const uint8_t *kept,
                     size_t tet_count, const uint32_t *tet, const uint32_t *adj,
                     size_t hull_face_count, const uint32_t *hull_faces, fl_error *err);

/* Checks that every hidden ball's centre lies in the triangulated hull and that the ball is in
 * conflict with no tetrahedron containing its centre (its lifted point is above the lower hull). */
fl_status dt3_verify_hidden(const double *in, size_t n, size_t hidden_count, const uint32_t *hidden,
                            size_t tet_count, const uint32_t *tet, const uint32_t *adj,
                            fl_error *err);

#endif /* FL_DT3_INTERNAL_H */

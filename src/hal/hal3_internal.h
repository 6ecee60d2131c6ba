/* Internal interface of the 3D flintstone (HAL) module. Not part of the public API. */
#ifndef FL_HAL3_INTERNAL_H
#define FL_HAL3_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"
#include "mesh/halfedge.h"

#define FL_HAL3_NONE UINT32_MAX

/* Rounding margins of the floating balls (as FL_HAL2_REL): a stored squared radius is the
 * largest computed squared distance to a point it must hold; a computed squared distance is
 * within a few ulps of the true one, so "d2 > r2 (1 + REL) + ABS" proves a point outside. */
#define FL_HAL3_REL 1e-12
#define FL_HAL3_ABS 1e-290

static inline double fl_hal3_d2(const double *ball, const double *x)
{
    double dx = x[0] - ball[0], dy = x[1] - ball[1], dz = x[2] - ball[2];
    return dx * dx + dy * dy + dz * dz;
}

static inline int fl_hal3_outside_ball(const double *ball, const double *x)
{
    return fl_hal3_d2(ball, x) > ball[3] * (1 + FL_HAL3_REL) + FL_HAL3_ABS;
}

/* A piece of surface being cut (hal3_region.c): the faces of an open polyhedron and its
 * boundary loop, a cyclic vertex sequence running with the surface's orientation (each directed
 * loop edge a->b is a half-edge of a face of the piece, unless the loop doubles back on itself),
 * with up to 6 marked corners (loop positions, increasing, cpos[0] = 0). */
typedef struct hal3_piece {
    uint32_t *faces;
    size_t nf;
    uint32_t *loop;
    size_t nl;
    uint32_t cpos[6];
    int nc;
} hal3_piece;

void hal3_piece_free(hal3_piece *pc);

/* Scratch of the cuts: stamps and Dijkstra state over the mesh. */
typedef struct hal3_work {
    const fl_mesh *mesh;
    const fl_halfedges *he;
    uint32_t stamp;
    uint32_t *face_mark, *edge_mark, *vert_mark, *vert_block, *dist_mark;
    uint32_t *seed_a, *seed_b; /* per half-edge: stamp when in loop A / B */
    uint8_t *label;            /* per face */
    double *dist;
    uint32_t *pred;
    uint32_t *heap_v;
    double *heap_d;
    size_t heap_cap;
    uint32_t *queue;
} hal3_work;

fl_status hal3_work_init(hal3_work *w, const fl_mesh *mesh, const fl_halfedges *he);
void hal3_work_free(hal3_work *w);

/* The half-edge a->b (a face's side), or FL_HAL3_NONE. */
uint32_t hal3_halfedge(const hal3_work *w, uint32_t a, uint32_t b);

/* Cuts piece `pc` along a shortest edge path between its corners u and w (corner indices,
 * u < w), through vertex `via` when via != FL_HAL3_NONE (both halves from one shortest-path
 * tree rooted at via, so they do not cross). *a receives the part whose loop runs from corner u
 * to corner w along pc's loop and back along the path, *b the other part; via becomes a corner
 * of both. Returns FL_ERR_NOMEM or FL_ERR_ALGORITHM (no path; inconsistent labelling). */
fl_status hal3_cut(hal3_work *w, const hal3_piece *pc, int u, int wc, uint32_t via, hal3_piece *a,
                   hal3_piece *b, fl_error *err);

/* Splits the whole surface along the cycle of shortest paths i->j->k->i into the part on the
 * left of the cycle (*a, loop i..j..k) and the part on the right (*b, loop i..k..j). */
fl_status hal3_cut_sphere(hal3_work *w, uint32_t i, uint32_t j, uint32_t k, hal3_piece *a,
                          hal3_piece *b, fl_error *err);

/* Smallest enclosing ball (Welzl, floating) of the n points; ball = centre, r^2; sup receives
 * up to 4 support vertices, *nsup their number. */
void hal3_min_ball(const double *xyz, size_t n, double ball[4], uint32_t sup[4], int *nsup);

/* Fills node's flintstone, widths and error from its piece (hal3_flintstone.c), and returns
 * the vertex for a three-split (an interior vertex of the piece, Def. 7.5's v_q or v_r, the one
 * with the larger signed radius) or FL_HAL3_NONE when the piece has no interior vertex. */
uint32_t hal3_flintstone(hal3_work *w, fl_hal3_node *node, const hal3_piece *pc);

/* Leaf geometry: ball around the triangle. */
void hal3_leaf_ball(const fl_mesh *mesh, fl_hal3_node *node);

#endif /* FL_HAL3_INTERNAL_H */

/* Meshsweeper internals (Guéziec 2001): the hierarchy of swept-sphere bounding elements shared
 * by the polyline (§3) and mesh (§4) builders and the priority-process queries. */
#ifndef FL_SWEEP_INTERNAL_H
#define FL_SWEEP_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

#define FL_SWEEP_LEAF UINT32_MAX

/* Per node, the box of its leaves' corners (boxes.c) and, in the same 64-byte record (the
 * array is 64-byte aligned), the children a descent reads next: a search through the boxes
 * touches one cache line a node instead of two (issue #9: on armadillo's random stream the
 * depth-first search waited on those two loads for half its time). */
typedef struct fl_sweep_box {
    double b[6];       /* lo[3], hi[3] */
    uint32_t child[2]; /* as the node's: child[0] = FL_SWEEP_LEAF for a leaf */
    uint32_t pad[2];
} fl_sweep_box;

/* One bounding element: the points within `eps` of a segment (v[0..5]) or a triangle
 * (v[0..8]), §3.1 / §4.1. A leaf is an input element itself (eps = 0). `rep` is a point of
 * the shape inside the element (meshes only; see query.c for why). */
typedef struct fl_sweep_node {
    double v[9];
    double rep[3];
    double eps;
    uint32_t child[2]; /* internal: both children; leaf: child[0] = FL_SWEEP_LEAF */
    uint32_t element;  /* leaf: the input segment / triangle index */
} fl_sweep_node;

struct fl_sweep {
    int dim;         /* of the query points: 2 or 3 */
    int triangles;   /* 1: nodes are triangles; 0: segments */
    size_t elements; /* input elements (leaves) */
    size_t node_count;
    fl_sweep_node *nodes; /* nodes[0] is the root */
    double scale;         /* largest |coordinate| of the input, for rounding slack */
    /* Meshes: the triangles' vertex indices, kept for fl_sweep_update_vertices (dynamic.c). */
    uint32_t *tri;
    size_t vertex_count;
    /* §5.2/§5.3: every update adds its largest vertex displacement to `moved` and counts
     * itself in `updates`; a cursor widens its kept intervals by the increase (query.c). */
    double moved;
    uint64_t updates;
    /* Per node, its box and children (boxes.c). NULL: not used. */
    fl_sweep_box *box;
};

/* Closest point on segment ab to p; *t in [0,1] is its parameter. Returns the squared
 * distance. Handles a = b. */
double fl_sweep_segment_closest(const double *p, const double *a, const double *b, double *t,
                                double *closest);

/* Closest point on triangle abc to p with its barycentric coordinates (bary sums to 1).
 * Returns the squared distance. Handles degenerate (collinear, repeated-vertex) triangles. */
double fl_sweep_triangle_closest(const double *p, const double *a, const double *b, const double *c,
                                 double *bary, double *closest);

/* Distance from p to the base element of a node, with its closest point and barycentrics. */
double fl_sweep_node_distance(const fl_sweep *s, const fl_sweep_node *node, const double *p,
                              double *bary, double *closest);

/* A bounding radius widened by the rounding error of the distances it was measured with (a
 * few ulps of the largest coordinate), so the volume contains its points for certain. */
static inline double fl_sweep_widen(double eps, double scale)
{
    return eps + 64 * 2.220446049250313e-16 * (eps + scale);
}

/* Largest accepted |coordinate|: squared distances between such points stay finite. */
#define FL_SWEEP_MAX_COORD 1e150

static inline int fl_sweep_coord_ok(double x)
{
    return fabs(x) <= FL_SWEEP_MAX_COORD; /* false for NaN and infinities too */
}

/* Checks n coordinates for new positions of a moving shape: the index of the first one that
 * fails fl_sweep_coord_ok, or n when all pass, in which case *scale has grown to the largest
 * |coordinate| (the rounding slack's scale only grows). */
static inline size_t fl_sweep_coords_scale(const double *x, size_t n, double *scale)
{
    double s = *scale;
    for (size_t i = 0; i < n; i++) {
        if (!fl_sweep_coord_ok(x[i])) return i;
        s = fmax(s, fabs(x[i]));
    }
    *scale = s;
    return n;
}

static inline int fl_sweep_is_leaf(const fl_sweep_node *node)
{
    return node->child[0] == FL_SWEEP_LEAF;
}

/* The rounding slack of the distances from q3 (64 ulps of the largest coordinate involved):
 * query bounds are widened by it so that no region is misjudged because of rounding. */
static inline double fl_sweep_query_slack(const fl_sweep *s, const double *q3)
{
    double m = fmax(fmax(fabs(q3[0]), fabs(q3[1])), fabs(q3[2]));
    return 64 * 2.220446049250313e-16 * (s->scale + m);
}

/* Lifts a query of dimension s->dim to 3D (z = 0 for 2D); 0 if a coordinate is not finite or
 * exceeds FL_SWEEP_MAX_COORD. */
int fl_sweep_lift_query(const fl_sweep *s, const double *q, double *q3);

/* Rigid motion (rigid.c, §5.2), shared by the spatial and the edge-collapse cursors: checks a
 * pose for a shape of dimension dim (FL_ERR_INPUT with a message); carries a world query (dim
 * doubles) into the shape's frame, Rᵀ (q − t), 0 if a coordinate is not finite or beyond
 * FL_SWEEP_MAX_COORD; carries an answer's point back to the world frame, R p + t. */
fl_status fl_sweep_pose_check(int dim, const fl_sweep_pose *pose, fl_error *err);
int fl_sweep_pose_to_local(int dim, const fl_sweep_pose *pose, const double *q, double *local);
void fl_sweep_pose_to_world(const fl_sweep_pose *pose, fl_closest *r);

/* The hierarchy a cursor searches (query.c). */
const fl_sweep *fl_sweep_cursor_sweep(const fl_sweep_cursor *cursor);

/* An uninitialised, 64-byte aligned box array of n records (free with free()); NULL when out
 * of memory or n records overflow. */
fl_sweep_box *fl_sweep_box_alloc(size_t n);

/* (Re)computes s->box bottom-up from the leaves' corners; leaves it NULL when out of memory
 * (the boxes only speed queries up) or when a child is numbered before its parent. */
void fl_sweep_compute_boxes(fl_sweep *s);

/* Asks the kernel (Linux: madvise MADV_HUGEPAGE) to back a freshly allocated, not yet touched
 * block of at least 4 MiB with huge pages: the first touch of every 4 KiB page costs a fault
 * of several microseconds on a virtual machine, and the node and box arrays of a large
 * hierarchy are thousands of pages (issue #9: a build in a fresh process spent more time in
 * page faults than in geometry). A hint only; elsewhere it does nothing (boxes.c). */
void fl_sweep_advise_huge(void *p, size_t bytes);

/* Squared distance from q to the box b (lo[3], hi[3]); 0 inside. */
static inline double fl_sweep_box_dist2(const double *b, const double *q)
{
    double d2 = 0;
    for (int c = 0; c < 3; c++) {
        double below = b[c] - q[c], above = q[c] - b[3 + c];
        double t = below > above ? below : above;
        if (t > 0) d2 += t * t;
    }
    return d2;
}

/* Allocates the sweep and its node array (2 * elements - 1 nodes). */
fl_status fl_sweep_alloc(int dim, int triangles, size_t elements, fl_sweep **out, fl_error *err);

/* ---- moving shapes (h-sweepdyn: keyframes.c, polyline_motion.c) ----
 * For a polyline hierarchy, fl_sweep.vertex_count is its point count n (tri stays NULL):
 * leaf e is the segment p_e p_{(e+1) mod n} and an internal node's base is its chain's chord,
 * which fl_sweep_polyline_update moves with the chain's end points. A key-frame hierarchy
 * (keyframes.c) is an ordinary mesh hierarchy whose nodes are rewritten at every time. */
/* ---- end of moving shapes ---- */

/* ==== walk region (walk.c, issue #9: coherent walks) ==== */

/* Most members a walk region keeps: enough for the triangles around a vertex a few steps
 * wide; a region that would hold more keeps the nearest and lowers its bound. */
#define FL_SWEEP_WALK_CAP 64

/* A certified "answer cannot change" region for coherent streams, generalising §3.3's ball to
 * near-ties: at its centre c every region of the hierarchy outside `leaf[0..n)` is at least
 * `bound` away (lower bounds already widened for rounding), and member i was d[i] away
 * (ascending). A query q with t = |q - c| is answered by the nearest member as long as that
 * member's distance is at most bound - t: by the triangle inequality nothing outside comes
 * nearer than bound - t. */
typedef struct fl_sweep_walk {
    int valid;
    uint64_t updates; /* s->updates when built: a shape update invalidates the region */
    double center[3];
    double bound;
    double slack; /* the rounding slack of the distances taken at the centre */
    size_t n;
    uint32_t leaf[FL_SWEEP_WALK_CAP];
    double d[FL_SWEEP_WALK_CAP];
    uint32_t answer; /* the leaf of the last answer given through the region */
    double second;   /* a lower bound on every other leaf's distance at that query */
    size_t answered; /* queries answered inside a region (statistics for tests) */
    size_t built;    /* regions built */
    size_t trimmed;  /* members let go because a region was full */
    size_t boxes;    /* box distances computed while building regions */
} fl_sweep_walk;

/* Answers q3 from the region when certified: 1 with r filled (exact), else 0. */
int fl_sweep_walk_answer(const fl_sweep *s, fl_sweep_walk *w, const double *q3, fl_closest *r);

/* Builds the region around q3 for moves up to `reach` and answers q3 exactly: a depth-first
 * search from the root for every region whose lower bound is below the distance to `seed` (any
 * leaf: an upper bound) plus 2 reach. `stack` holds s->node_count ids. Returns 0 (no answer)
 * only if the search found no leaf, which rounding alone could cause. */
int fl_sweep_walk_build(const fl_sweep *s, fl_sweep_walk *w, const double *q3, double reach,
                        uint32_t seed, uint32_t *stack, fl_closest *r);

/* The walk statistics of a cursor (tests): queries answered inside a region, regions built,
 * members let go from full regions. */
void fl_sweep_cursor_walk_stats(const fl_sweep_cursor *cursor, size_t *answered, size_t *built,
                                size_t *trimmed);

/* Box distances a cursor has computed over all its queries (its regions' included): with the
 * distances (fl_closest.visited) the work of its queries, for tests comparing strategies. */
size_t fl_sweep_cursor_box_tests(const fl_sweep_cursor *cursor);

/* end of walk region */

#endif /* FL_SWEEP_INTERNAL_H */

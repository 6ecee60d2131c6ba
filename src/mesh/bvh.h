/* Axis-aligned bounding box hierarchy over primitives given by their boxes (internal; 2D users
 * pass z = 0). Built top-down by median split of the box centres along the widest axis, so
 * the tree is balanced (depth <= log2(n) + 1) whatever the input. Flat arrays; the children of
 * an internal node are adjacent and follow it. Boxes are stored as floats rounded outward, so
 * they contain the exact double boxes: a candidate search never misses a pair whose closed
 * boxes touch (it may report a few more, which the caller's exact test rejects). */
#ifndef FL_MESH_BVH_H
#define FL_MESH_BVH_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

typedef struct fl_bvh_node {
    float box[6];   /* min xyz, max xyz of everything below (rounded outward) */
    uint32_t left;  /* internal: left child (right child is left + 1); leaf: 0 */
    uint32_t start; /* leaf: first entry in fl_bvh.prim */
    uint32_t count; /* leaf: number of primitives (>= 1); internal: 0 */
} fl_bvh_node;

typedef struct fl_bvh {
    size_t node_count;
    fl_bvh_node *nodes; /* nodes[0] is the root (when node_count > 0) */
    size_t prim_count;
    uint32_t *prim;  /* primitive ids in leaf order */
    float *prim_box; /* 6 per entry of prim, in the same order (rounded outward) */
} fl_bvh;

/* Builds the hierarchy over n boxes (6 doubles each: min xyz, max xyz; primitive i is
 * boxes[6i..6i+5]) with at most leaf_size (1..16) primitives per leaf. `ids` (may be NULL =
 * 0..n-1) gives the id reported for box i. n must be < 2^31. */
fl_status fl_bvh_build(const double *boxes, const uint32_t *ids, size_t n, int leaf_size,
                       fl_bvh *bvh, fl_error *err);

void fl_bvh_free(fl_bvh *bvh);

/* Called for each unordered pair of distinct primitives whose closed boxes overlap. Return
 * nonzero to stop the search. */
typedef int (*fl_bvh_pair_fn)(void *user, uint32_t a, uint32_t b);

/* Enumerates all overlapping pairs by a simultaneous descent of the tree against itself.
 * `progress` (may be NULL) is called now and then with the fraction of leaves done, under
 * `stage`. Returns 0 when complete, 1 when fn or progress asked to stop. */
int fl_bvh_self_pairs(const fl_bvh *bvh, fl_bvh_pair_fn fn, void *user, fl_progress_fn progress,
                      void *progress_user, const char *stage);

#endif /* FL_MESH_BVH_H */

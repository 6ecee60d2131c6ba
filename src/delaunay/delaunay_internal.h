/* Internal interface shared by the 2D and 3D triangulations of src/delaunay: exact duplicate
 * detection and the spatial insertion order (src/delaunay/sort.c). Not part of the public API. */
#ifndef FL_DELAUNAY_INTERNAL_H
#define FL_DELAUNAY_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "core/core.h"

/* Exact duplicate detection. `coords` holds n points of dimension `dim` (2 or 3), interleaved.
 * On success rep[i] (n entries, caller-allocated) is the smallest index j <= i whose coordinates
 * are identical to point i's (so rep[i] == i iff i is the first of its kind), and *unique_count
 * is the number of i with rep[i] == i. "Identical" is bitwise equality after mapping -0.0 to
 * +0.0, i.e. exactly the equality the exact predicates see. Expected O(n) (hashing).
 * Errors: FL_ERR_USAGE (dim not 2 or 3, NULL buffers), FL_ERR_INPUT (NaN or infinite
 * coordinate, naming the point; n > UINT32_MAX - 1), FL_ERR_NOMEM. */
fl_status fl_dt_unique(const double *coords, size_t n, int dim, uint32_t *rep, size_t *unique_count,
                       fl_error *err);

/* Biased randomized insertion order (Amenta, Choi, Rote 2003) of the n points named by `ids`
 * (indices into `coords`; NULL means 0..n-1). Each point is put in a random round (a fixed hash
 * of its id, so the order is deterministic): the last round holds about 7/8 of the points, the
 * round before 7/8 of the rest, and so on; within a round the points follow a Hilbert curve over
 * the bounding box of all n points. Consecutive points are thus close (short walks during point
 * location) while the rounds keep the expected cost of randomized incremental construction.
 * Writes the n ids, permuted, into order_out (n entries, caller-allocated, may not alias ids).
 * O(n) time (one radix sort of 64-bit (round, Hilbert) keys).
 * Errors: FL_ERR_USAGE (dim not 2 or 3, NULL buffers), FL_ERR_INPUT (NaN or infinite
 * coordinate, naming the point; n > UINT32_MAX - 1), FL_ERR_NOMEM. */
fl_status fl_dt_brio_order(const double *coords, const uint32_t *ids, size_t n, int dim,
                           uint32_t *order_out, fl_error *err);

/* The same two in caller-provided scratch memory (8-byte aligned, at least the bytes given by
 * the _scratch_bytes function for n points; NULL or smaller: they allocate their own). On this
 * kind of machine the first touch of fresh pages costs as much as the triangulation's
 * arithmetic, so a caller that needs a big buffer later anyway lends it here and its pages are
 * touched once. */
size_t fl_dt_unique_scratch_bytes(size_t n);
size_t fl_dt_brio_scratch_bytes(size_t n);
fl_status fl_dt_unique_in(const double *coords, size_t n, int dim, uint32_t *rep,
                          size_t *unique_count, void *scratch, size_t scratch_bytes, fl_error *err);
fl_status fl_dt_brio_order_in(const double *coords, const uint32_t *ids, size_t n, int dim,
                              uint32_t *order_out, void *scratch, size_t scratch_bytes,
                              fl_error *err);

/* ==== 2D triangulation in its insertion numbering (for src/reconstruct) ====
 * fl_dt2_build's triangulation (the same triangles in the same order, the same hull) before its
 * vertices are mapped back to input indices: vertex r is the r-th distinct point of the BRIO
 * insertion order, order[r] its input index, xy[2r], xy[2r + 1] its coordinates. Consecutive
 * ranks are close in the plane, so a caller that walks the triangulation along a front (2D
 * constriction) gets mostly local memory accesses without gathering the shuffled input a second
 * time. `order` holds the first input index of each distinct point; duplicate_of is as in
 * fl_dt2. Free with fl_dt2_ranked_free. Errors as fl_dt2_build (want_circumcenters is ignored). */
typedef struct fl_dt2_ranked {
    size_t point_count, unique_count;
    uint32_t *duplicate_of; /* point_count: as fl_dt2.duplicate_of (input indices) */
    uint32_t *order;        /* unique_count: rank -> input index */
    double *xy;             /* 2 per rank */
    size_t triangle_count;
    uint32_t *tri, *adj; /* 3 per triangle: ranks, counterclockwise; neighbours or UINT32_MAX */
    size_t hull_count;
    uint32_t *hull; /* ranks, counterclockwise, as fl_dt2.hull */
    /* The rest of tri's allocation after the triangles (16-byte aligned; memory the build has
     * touched already, so no page faults on first use): free for the caller's scratch until
     * tri is freed or reallocated. NULL when there is none. */
    void *spare;
    size_t spare_bytes;
} fl_dt2_ranked;

fl_status fl_dt2_build_ranked(const double *xy, size_t n, const fl_dt2_options *opt,
                              fl_dt2_ranked *out, fl_error *err);
void fl_dt2_ranked_free(fl_dt2_ranked *dt);
/* end of 2D triangulation in its insertion numbering */

#endif /* FL_DELAUNAY_INTERNAL_H */

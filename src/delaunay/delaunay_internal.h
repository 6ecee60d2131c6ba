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
 * (indices into `coords`; NULL means 0..n-1). The ids are shuffled with a fixed seed (so the
 * order is deterministic), split into rounds of geometrically growing size (the last round
 * holds 7/8 of the points, the round before 7/8 of the rest, ...), and each round is sorted
 * along a Hilbert curve over the bounding box of all n points. Consecutive points are thus
 * close (short walks during point location) while the rounds keep the expected cost of
 * randomized incremental construction. Writes the n ids, permuted, into order_out (n entries,
 * caller-allocated, may not alias ids). O(n) time (radix sort of 64-bit Hilbert keys).
 * Errors: FL_ERR_USAGE (dim not 2 or 3, NULL buffers), FL_ERR_INPUT (NaN or infinite
 * coordinate, naming the point; n > UINT32_MAX - 1), FL_ERR_NOMEM. */
fl_status fl_dt_brio_order(const double *coords, const uint32_t *ids, size_t n, int dim,
                           uint32_t *order_out, fl_error *err);

#endif /* FL_DELAUNAY_INTERNAL_H */

/* Internal interface of the 2D flintstone (HAL) module. Not part of the public API. */
#ifndef FL_HAL2_INTERNAL_H
#define FL_HAL2_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

/* Rounding margins of the floating discs. A stored disc is (cx, cy, r2) with r2 the largest
 * computed squared distance from the centre to a vertex it must hold. A computed squared
 * distance a^2 + b^2 of differences a, b is within 5 ulps (relative 6e-16) of the true one
 * unless it underflows, where the absolute error is below 1e-300. Testing
 * "computed d2 > r2 * (1 + FL_HAL2_REL) + FL_HAL2_ABS" with a margin of ~90 ulps therefore
 * proves the point outside the disc of true radius^2 >= every vertex's true distance^2, and
 * that disc contains the whole polyline and its chord (a disc is convex). */
#define FL_HAL2_REL 1e-14
#define FL_HAL2_ABS 1e-290

/* Squared distance from (x, y) to a disc's centre. */
static inline double fl_hal2_d2(const double *disc, double x, double y)
{
    double dx = x - disc[0], dy = y - disc[1];
    return dx * dx + dy * dy;
}

/* 1 when (x, y) is provably outside the stored disc (see above), 0 when it may be inside. */
static inline int fl_hal2_outside_disc(const double *disc, double x, double y)
{
    return fl_hal2_d2(disc, x, y) > disc[2] * (1 + FL_HAL2_REL) + FL_HAL2_ABS;
}

/* Smallest enclosing disc of the n points xy[2 idx[k]], xy[2 idx[k] + 1] (hal2_sbd.c), by
 * randomized incremental construction (Welzl) in expected O(n) time with exact in-circle
 * decisions; idx is shuffled in place (deterministically). Writes the two points on the
 * circle that are farthest apart (two sweeps over the cocircular points) to *i, *j and the
 * disc (centre, enlarged squared radius) to disc. n >= 2. */
void fl_hal2_sbd(const double *xy, uint32_t *idx, size_t n, uint32_t *i, uint32_t *j,
                 double disc[3]);

/* A polyline waiting for its node: ring-local positions p < s (s may pass the ring's end),
 * its level, and where the new node's index goes. */
typedef struct hal2_pending {
    uint32_t p, s, level;
    int32_t *slot;
} hal2_pending;

/* (Re)builds ring `ring`'s tree from its smallest enclosing disc (hal2_build.c), appending
 * nodes to hal->nodes, which must have room for one node a ring vertex; order and stack need
 * one entry a ring vertex. */
void fl_hal2_build_ring(fl_hal2 *hal, uint32_t ring, uint32_t *order, hal2_pending *stack);

/* Builds the subtree of the polyline at ring-local positions p..s (s >= p + 2) at `level`,
 * storing its root's index in *slot. Same room requirements. */
void fl_hal2_rebuild_node(fl_hal2 *hal, uint32_t ring, int32_t *slot, uint32_t p, uint32_t s,
                          uint32_t level, hal2_pending *stack);

#endif /* FL_HAL2_INTERNAL_H */

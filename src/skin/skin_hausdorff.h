/* The ball index behind fl_skin_union_hausdorff (skin_hausdorff_balls.c): the queries on a
 * union of balls that the certified Hausdorff distance of its boundary needs. */
#ifndef FL_SKIN_HAUSDORFF_H
#define FL_SKIN_HAUSDORFF_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

/* The balls of positive weight as (x, y, z, r) rows, and a uniform grid listing each ball in
 * every cell its bounding box meets (CSR: start[cells + 1], item[]). A ball containing a point
 * is therefore listed in the point's cell. */
typedef struct skin_ball_grid {
    size_t n;
    double *xyzr;
    double rmax;
    double origin[3], cell;
    size_t dims[3];
    size_t *start;
    uint32_t *item;
} skin_ball_grid;

/* Builds the grid over the balls' boxes and the box lo..hi (the mesh's, so its points have
 * cells). FL_ERR_INPUT when no ball has a positive weight or a value is not finite / beyond
 * 1e150, FL_ERR_NOMEM. */
fl_status skin_ball_grid_build(const fl_balls *balls, const double lo[3], const double hi[3],
                               skin_ball_grid *g, fl_error *err);
void skin_ball_grid_free(skin_ball_grid *g);

/* 1 when the ball of radius delta around p lies inside a ball other than `skip` (its open
 * interior, with a margin `slack`). */
int skin_ball_grid_buried(const skin_ball_grid *g, const double p[3], double delta, double slack,
                          size_t skip);

/* 1 when p lies in no open ball other than `skip` (p on sphere skip is then on the boundary of
 * the union, to rounding). */
int skin_ball_grid_exposed(const skin_ball_grid *g, const double p[3], size_t skip);

/* min over the balls of |p - c| - r: the distance from p to the union when >= 0; when < 0,
 * minus the largest depth of p in one ball, a lower bound on p's distance to the boundary. */
double skin_ball_grid_signed(const skin_ball_grid *g, const double p[3]);

/* For p in the union: the parameter s >= 0 where the ray p + s dir (dir a unit vector) leaves
 * the union, up to `slack`: the point there lies on the union's boundary, so s bounds p's
 * distance to it from above. */
double skin_ball_grid_ray_exit(const skin_ball_grid *g, const double p[3], const double dir[3],
                               double slack);

#endif

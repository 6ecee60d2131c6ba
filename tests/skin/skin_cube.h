/* The unit cube [0,1]^3 as a closed triangle mesh, outward oriented, for the skin tests. */
#ifndef FL_TEST_SKIN_CUBE_H
#define FL_TEST_SKIN_CUBE_H

#include <stdint.h>

#include "flintstone.h"

static const double skin_cube_xyz[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                       0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
static const uint32_t skin_cube_tri[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                         1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

static inline fl_mesh skin_cube_mesh(void)
{
    fl_mesh m = {0};
    m.vertex_count = 8;
    m.triangle_count = 12;
    m.xyz = (double *)skin_cube_xyz;
    m.tri = (uint32_t *)skin_cube_tri;
    return m;
}

/* B* of the unit cube's approximation within eps: one round, uniform grid only. */
static inline fl_status skin_cube_bstar(double eps, fl_skin_approx *a, fl_error *err)
{
    fl_mesh m = skin_cube_mesh();
    fl_skin_approx_options o = {0};
    o.max_rounds = 1;
    o.grade = -1;
    return fl_skin_approx_build(&m, eps, &o, a, err);
}

#endif /* FL_TEST_SKIN_CUBE_H */

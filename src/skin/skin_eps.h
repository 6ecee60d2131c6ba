/* Internals of the ε-approximation of a polyhedron (skin_balls.c, skin_star.c, skin_approx.c). */
#ifndef FL_SKIN_EPS_H
#define FL_SKIN_EPS_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

/* Balls of radius rho centred on a conforming sampling of the closed mesh m that covers it. */
fl_status skin_eps_surface_balls(const fl_mesh *m, double rho, fl_balls *out, fl_error *err);

/* Generalised winding number of the closed oriented mesh m around x (1 inside, 0 outside). */
double skin_eps_winding(const fl_mesh *m, const double x[3]);

/* B_perp and B* of the surface balls b (§5, §6.2) for the object bounded by m. */
fl_status skin_eps_orthogonal_balls(const fl_mesh *m, const fl_balls *b, fl_balls *perp,
                                    fl_balls *star, fl_error *err);

#endif

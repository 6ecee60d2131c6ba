/* Internals of the ε-approximation of a polyhedron (skin_lgs.c, skin_balls.c, skin_star.c,
 * skin_approx.c). */
#ifndef FL_SKIN_EPS_H
#define FL_SKIN_EPS_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

/* A uniform grid of the triangles of a mesh (CSR lists by bounding box), for the local gap
 * size and the inside test. Queries are not thread-safe (they stamp visited triangles). */
typedef struct skin_eps_grid {
    const fl_mesh *mesh;
    double origin[3], cell;
    size_t dims[3];
    size_t *start;
    uint32_t *item;
    uint32_t *stamp, epoch;
} skin_eps_grid;

fl_status skin_eps_grid_build(const fl_mesh *m, double reach, skin_eps_grid *g, fl_error *err);
void skin_eps_grid_free(skin_eps_grid *g);

/* min(reach, lgs(p)) for p in the relative interior of its carrier: kind 0 = vertex ids[0],
 * 1 = edge ids[0..1], 2 = triangle carrier_tri (Cheng & Tan §4). */
double skin_eps_lgs(skin_eps_grid *g, const double *p, int kind, const uint32_t *ids,
                    size_t carrier_tri, double reach);

/* 1 when p is inside the closed oriented mesh (ray parity, winding number near degeneracies). */
int skin_eps_inside(skin_eps_grid *g, const double *p);

double skin_eps_dist_segment(const double *p, const double *a, const double *b);

/* Generalised winding number of the closed oriented mesh m around x (1 inside, 0 outside). */
double skin_eps_winding(const fl_mesh *m, const double x[3]);

/* The protecting balls B (§4): radii <= rmax and < gamma lgs(centre), centres on the mesh,
 * covering it, with carrier[i] = 0/1/2 (vertex/edge/triangle) and the carrier's index in
 * carrier_id[i] (vertex index, edge index into the sorted unique edges, triangle index).
 * The arrays are malloc'ed. FL_ERR_ALGORITHM when the subdivision would exceed max_balls or
 * its depth cap. placement: FL_SKIN_PLACE_ALGORITHM1 (skin_alg1.c, §4.2) or
 * FL_SKIN_PLACE_SUBDIVISION (skin_balls.c). */
typedef struct skin_eps_sample {
    fl_balls balls;
    uint8_t *carrier;
    uint32_t *carrier_id;
    size_t boundary_count; /* balls on vertices and edges */
} skin_eps_sample;

fl_status skin_eps_surface_balls(const fl_mesh *m, double rmax, double gamma, size_t max_balls,
                                 int placement, skin_eps_sample *out, fl_error *err);
void skin_eps_sample_free(skin_eps_sample *s);

/* B_perp and B* of the surface balls b (§5, §6.2) for the object bounded by m. */
fl_status skin_eps_orthogonal_balls(skin_eps_grid *g, const fl_balls *b, fl_balls *perp,
                                    fl_balls *star, fl_error *err);

#endif

/* The state shared by the two placements of the protecting balls B (Cheng & Tan §4):
 * skin_balls.c (subdivision) and skin_alg1.c (Algorithm 1 of §4.2, restricted power diagrams).
 * Internal to src/skin. */
#ifndef FL_SKIN_SAMPLER_H
#define FL_SKIN_SAMPLER_H

#include <stddef.h>
#include <stdint.h>

#include "core/core.h"
#include "skin/skin_eps.h"

typedef struct skin_sampler {
    const fl_mesh *m;
    skin_eps_grid grid;
    double rmax, gamma, reach;
    size_t max_balls, work, max_work;
    uint32_t *edge; /* unique edges, 2 sorted vertex ids each */
    size_t ne;
    uint32_t *vball;            /* ball index of each vertex */
    size_t *edge_first;         /* balls of edge e: [edge_first[e], edge_first[e + 1]) */
    fl_vec balls, carrier, cid; /* 4 doubles, uint8, uint32 per ball */
} skin_sampler;

/* Appends the ball (p, r^2) with carrier kind (0/1/2) and carrier index id; FL_ERR_INPUT past
 * max_balls or for r <= 0 (zero local gap size). */
fl_status skin_sampler_push(skin_sampler *s, const double *p, double r, uint8_t kind, uint32_t id,
                            fl_error *err);

/* min(gamma lgs(p), rmax) for p in the relative interior of its carrier (skin_eps_lgs). */
double skin_sampler_radius(skin_sampler *s, const double *p, int kind, const uint32_t *ids,
                           size_t tri);

/* Counts one unit of work; FL_ERR_ALGORITHM past the work cap or when depth > cap. */
fl_status skin_sampler_tick(skin_sampler *s, int depth, int cap, fl_error *err);

/* Index of the edge {a, b} in s->edge. */
size_t skin_sampler_edge_index(const skin_sampler *s, uint32_t a, uint32_t b);

/* Algorithm 1 (skin_alg1.c): the balls of edge e / triangle f at positive restricted Voronoi
 * vertices, after those of its boundary. */
fl_status skin_alg1_edge(skin_sampler *s, size_t e, fl_error *err);
fl_status skin_alg1_triangle(skin_sampler *s, size_t f, fl_vec *bl, fl_error *err);

#endif

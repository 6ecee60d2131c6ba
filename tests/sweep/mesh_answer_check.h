/* The exact-answer check shared by the mesh hierarchy tests (test_mesh.c, test_sweep_dynamic.c,
 * the collapse tests): brute force over every triangle with the independent long-double oracle. */
#ifndef MESH_ANSWER_CHECK_H
#define MESH_ANSWER_CHECK_H

#include <math.h>

#include "fl_test.h"
#include "sweep_oracle.h"

/* Largest absolute coordinate: the scale of the rounding tolerances. */
static inline double mesh_scale(const fl_mesh *m)
{
    double s = 0;
    for (size_t i = 0; i < 3 * m->vertex_count; i++)
        s = fmax(s, fabs(m->xyz[i]));
    return s;
}

/* The distance from q to the mesh, every triangle tried. */
static inline ld brute_distance(const fl_mesh *m, const double *q)
{
    ld best = INFINITY;
    for (size_t t = 0; t < m->triangle_count; t++) {
        ld d = oracle_mesh_element(m->xyz, m->tri, t, q);
        if (d < best) best = d;
    }
    return best;
}

/* One exact answer against brute force over the mesh as it is now: the distance to 1e-12
 * relative, the element at that distance (the same triangle or an equidistant one), and
 * point = sum bary * vertices at that distance from q. */
static inline void check_exact(const fl_mesh *m, const double *q, const fl_closest *r)
{
    double tol = 1e-12 * (mesh_scale(m) + fabs(q[0]) + fabs(q[1]) + fabs(q[2]));
    ld bf = brute_distance(m, q);
    CHECK(r->exact);
    CHECK_NEAR(r->distance, (double)bf, tol);
    CHECK(r->element < m->triangle_count);
    if (r->element >= m->triangle_count) return;
    CHECK_NEAR((double)oracle_mesh_element(m->xyz, m->tri, r->element, q), (double)bf, tol);
    double dp = 0;
    for (int c = 0; c < 3; c++) {
        double x = 0;
        for (int k = 0; k < 3; k++)
            x += r->bary[k] * oracle_vertex(m->xyz, m->tri, r->element, k)[c];
        CHECK_NEAR(x, r->point[c], tol);
        dp += (q[c] - r->point[c]) * (q[c] - r->point[c]);
    }
    CHECK_NEAR(sqrt(dp), r->distance, tol);
}

#endif

/* Test meshes and brute-force checks shared by the collapse-hierarchy tests (closed, open,
 * non-manifold and degenerate; distances by sweep_oracle.h, which shares no code with src/). */
#ifndef TEST_COLLAPSE_MESHES_H
#define TEST_COLLAPSE_MESHES_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"
#include "mesh_answer_check.h"

static unsigned long long cm_rng = 0xc011a95eULL;

static inline double cm_rand(double lo, double hi)
{
    return lo + (hi - lo) * fl_test_rand01(&cm_rng);
}

static inline fl_mesh cm_alloc(size_t nv, size_t nt)
{
    fl_mesh m = {nv, calloc(3 * nv, sizeof(double)), nt, calloc(3 * nt, sizeof(uint32_t))};
    return m;
}

static inline void cm_free(fl_mesh *m)
{
    free(m->xyz);
    free(m->tri);
}

/* A closed torus-like surface, nu x nv quads split in two, with random radial noise. */
static inline fl_mesh cm_noisy_torus(int nu, int nv, double noise)
{
    fl_mesh m = cm_alloc((size_t)nu * nv, 2 * (size_t)nu * nv);
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double a = 6.283185307179586 * i / nu, b = 6.283185307179586 * j / nv;
            double r = 0.35 * (1 + cm_rand(-noise, noise));
            double *p = m.xyz + 3 * ((size_t)i * nv + j);
            p[0] = (1 + r * cos(b)) * cos(a), p[1] = (1 + r * cos(b)) * sin(a), p[2] = r * sin(b);
        }
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            uint32_t v00 = (uint32_t)(i * nv + j), v10 = (uint32_t)(((i + 1) % nu) * nv + j);
            uint32_t v11 = (uint32_t)(((i + 1) % nu) * nv + (j + 1) % nv);
            uint32_t v01 = (uint32_t)(i * nv + (j + 1) % nv);
            uint32_t q[6] = {v00, v10, v11, v00, v11, v01};
            memcpy(m.tri + 6 * ((size_t)i * nv + j), q, sizeof q);
        }
    return m;
}

/* An open height field over an n x n grid (random heights plus a wave). */
static inline fl_mesh cm_open_grid(int n, double bump)
{
    fl_mesh m = cm_alloc((size_t)n * n, 2 * (size_t)(n - 1) * (n - 1));
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double *p = m.xyz + 3 * ((size_t)i * n + j);
            p[0] = (double)i / (n - 1), p[1] = (double)j / (n - 1);
            p[2] = 0.2 * sin(3 * p[0]) * cos(2 * p[1]) + cm_rand(-bump, bump);
        }
    size_t t = 0;
    for (int i = 0; i + 1 < n; i++)
        for (int j = 0; j + 1 < n; j++, t += 2) {
            uint32_t a = (uint32_t)(i * n + j), b = (uint32_t)((i + 1) * n + j);
            uint32_t q[6] = {a, b, b + 1, a, b + 1, a + 1};
            memcpy(m.tri + 3 * t, q, sizeof q);
        }
    return m;
}

/* The open grid plus trouble: three extra triangles on one interior edge (non-manifold), a
 * collinear and a repeated-vertex triangle, a vertex duplicating a grid vertex used by a
 * triangle, and a repeated triangle. */
static inline fl_mesh cm_messy(int n)
{
    fl_mesh g = cm_open_grid(n, 0.01);
    size_t nv = g.vertex_count + 6, nt = g.triangle_count + 7;
    fl_mesh m = cm_alloc(nv, nt);
    memcpy(m.xyz, g.xyz, 3 * g.vertex_count * sizeof(double));
    memcpy(m.tri, g.tri, 3 * g.triangle_count * sizeof(uint32_t));
    uint32_t b = (uint32_t)g.vertex_count, e0 = (uint32_t)(n + 1), e1 = (uint32_t)(2 * n + 2);
    double extra[6][3] = {{0.3, 0.3, 0.5}, {0.3, 0.3, -0.5}, {0.1, 0.2, 0.6},
                          {1.5, 0, 0},     {2, 0.5, 0},      {0, 0, 0}};
    memcpy(m.xyz + 3 * (size_t)b, extra, sizeof extra);
    /* b+5 duplicates grid vertex 0; b+2 becomes the midpoint of b+3 b+4 (collinear) */
    double mid[3] = {1.75, 0.25, 0};
    memcpy(m.xyz + 3 * (size_t)(b + 2), mid, sizeof mid);
    uint32_t more[7][3] = {{e0, e1, b},         {e0, e1, b + 1},     {e1, e0, b + 2},
                           {b + 3, b + 4, b + 2}, {b + 3, b + 3, b + 4}, {b + 5, 1, (uint32_t)n},
                           {e0, e1, b}};
    memcpy(m.tri + 3 * g.triangle_count, more, sizeof more);
    cm_free(&g);
    return m;
}

/* n separate random triangles in the unit cube. */
static inline fl_mesh cm_soup(size_t n, double size)
{
    fl_mesh m = cm_alloc(3 * n, n);
    for (size_t t = 0; t < n; t++) {
        double c[3] = {cm_rand(0, 1), cm_rand(0, 1), cm_rand(0, 1)};
        for (int k = 0; k < 3; k++) {
            for (int x = 0; x < 3; x++)
                m.xyz[9 * t + 3 * k + x] = c[x] + cm_rand(-size, size);
            m.tri[3 * t + k] = (uint32_t)(3 * t + k);
        }
    }
    return m;
}

#endif /* TEST_COLLAPSE_MESHES_H */

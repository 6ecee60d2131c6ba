/* Closed test meshes built in code: octahedron, triangulated cube, icosphere, and a randomly
 * jittered icosphere (no symmetry left), all counter-clockwise seen from outside. */
#ifndef FL_TEST_G1_MESHES_H
#define FL_TEST_G1_MESHES_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"

static inline fl_mesh g1_mesh_from(const double *xyz, size_t nv, const uint32_t *tri, size_t nt)
{
    fl_mesh m = {nv, malloc(nv * 3 * sizeof(double)), nt, malloc(nt * 3 * sizeof(uint32_t))};
    memcpy(m.xyz, xyz, nv * 3 * sizeof(double));
    memcpy(m.tri, tri, nt * 3 * sizeof(uint32_t));
    return m;
}

static inline fl_mesh g1_octahedron(void)
{
    static const double v[] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    static const uint32_t t[] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    return g1_mesh_from(v, 6, t, 8);
}

static inline fl_mesh g1_cube(void)
{
    static const double v[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                               0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    static const uint32_t t[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    return g1_mesh_from(v, 8, t, 12);
}

/* Midpoint of edge (a, b) pushed to the unit sphere, created once through a small table. */
static inline uint32_t g1_mid(double *v, uint32_t *nv, uint32_t *key, uint32_t *val, uint32_t a,
                              uint32_t b)
{
    uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
    for (uint32_t i = 0; key[2 * i] != UINT32_MAX; i++)
        if (key[2 * i] == lo && key[2 * i + 1] == hi) return val[i];
    uint32_t i = 0;
    while (key[2 * i] != UINT32_MAX)
        i++;
    key[2 * i] = lo;
    key[2 * i + 1] = hi;
    key[2 * i + 2] = UINT32_MAX;
    double *p = v + 3 * *nv, s = 0;
    for (int d = 0; d < 3; d++) {
        p[d] = (v[3 * a + d] + v[3 * b + d]) / 2;
        s += p[d] * p[d];
    }
    for (int d = 0; d < 3; d++)
        p[d] /= sqrt(s);
    return val[i] = (*nv)++;
}

/* Icosahedron subdivided `levels` times (<= 3), vertices on the unit sphere; with jitter > 0
 * every vertex moves by up to `jitter` (seeded) so no edge keeps a symmetry. */
static inline fl_mesh g1_icosphere(int levels, double jitter, unsigned long long seed)
{
    const double g = (1 + sqrt(5.0)) / 2;
    double base[] = {-1, g,  0,  1, g, 0,  -1, -g, 0,  1, -g, 0, 0,  -1, g,  0,  1, g,
                     0,  -1, -g, 0, 1, -g, g,  0,  -1, g, 0,  1, -g, 0,  -1, -g, 0, 1};
    static const uint32_t ico[] = {0, 11, 5, 0, 5,  1,  0,  1,  7,  0,  7, 10, 0, 10, 11,
                                   1, 5,  9, 5, 11, 4,  11, 10, 2,  10, 7, 6,  7, 1,  8,
                                   3, 9,  4, 3, 4,  2,  3,  2,  6,  3,  6, 8,  3, 8,  9,
                                   4, 9,  5, 2, 4,  11, 6,  2,  10, 8,  6, 7,  9, 8,  1};
    size_t maxv = 12, maxt = 20;
    for (int l = 0; l < levels; l++)
        maxv += maxt * 3 / 2, maxt *= 4;
    double *v = malloc(maxv * 3 * sizeof(double));
    uint32_t *t = malloc(maxt * 3 * sizeof(uint32_t)), *t2 = malloc(maxt * 3 * sizeof(uint32_t));
    uint32_t *key = malloc((maxv * 2 + 2) * sizeof(uint32_t)),
             *val = malloc(maxv * sizeof(uint32_t));
    for (int i = 0; i < 12; i++) {
        double s = sqrt(1 + g * g);
        for (int d = 0; d < 3; d++)
            v[3 * i + d] = base[3 * i + d] / s;
    }
    memcpy(t, ico, sizeof ico);
    uint32_t nv = 12, nt = 20;
    for (int l = 0; l < levels; l++) {
        key[0] = UINT32_MAX;
        for (uint32_t i = 0; i < nt; i++) {
            uint32_t a = t[3 * i], b = t[3 * i + 1], c = t[3 * i + 2];
            uint32_t ab = g1_mid(v, &nv, key, val, a, b), bc = g1_mid(v, &nv, key, val, b, c);
            uint32_t ca = g1_mid(v, &nv, key, val, c, a);
            uint32_t q[12] = {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca};
            memcpy(t2 + 12 * i, q, sizeof q);
        }
        nt *= 4;
        memcpy(t, t2, nt * 3 * sizeof(uint32_t));
    }
    for (uint32_t i = 0; jitter > 0 && i < 3 * nv; i++)
        v[i] += jitter * (2 * fl_test_rand01(&seed) - 1);
    fl_mesh m = g1_mesh_from(v, nv, t, nt);
    free(v);
    free(t);
    free(t2);
    free(key);
    free(val);
    return m;
}

/* The surface of the cube [0, n]^3 with every face an n x n grid of squares, each split by a
 * diagonal (all in one direction), like CGAL's cube-meshed.off: flat regions, and vertices on
 * cube edges whose stars are seen almost edge-on. */
static inline fl_mesh g1_meshed_cube(int n)
{
    size_t side = (size_t)n + 1, nv = 0, nt = 0;
    uint32_t *id = malloc(side * side * side * sizeof(uint32_t));
    double *v = malloc(side * side * side * 3 * sizeof(double));
    uint32_t *t = malloc((size_t)12 * n * n * 3 * sizeof(uint32_t));
    for (size_t i = 0; i < side * side * side; i++)
        id[i] = UINT32_MAX;
    for (int axis = 0; axis < 3; axis++)
        for (int hi = 0; hi < 2; hi++)
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++) {
                    uint32_t q[4];
                    for (int c = 0; c < 4; c++) {
                        int g[3], u = i + (c == 1 || c == 2), w = j + (c >= 2);
                        g[axis] = hi * n;
                        g[(axis + 1) % 3] = u;
                        g[(axis + 2) % 3] = w;
                        size_t key = ((size_t)g[0] * side + (size_t)g[1]) * side + (size_t)g[2];
                        if (id[key] == UINT32_MAX) {
                            for (int d = 0; d < 3; d++)
                                v[3 * nv + d] = g[d];
                            id[key] = (uint32_t)nv++;
                        }
                        q[c] = id[key];
                    }
                    /* (u, w) axes are counter-clockwise seen from +axis; flip on the low side */
                    uint32_t a[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
                    if (!hi) {
                        uint32_t x = a[1];
                        a[1] = a[2], a[2] = x;
                        x = a[4], a[4] = a[5], a[5] = x;
                    }
                    memcpy(t + 3 * nt, a, sizeof a);
                    nt += 2;
                }
    fl_mesh m = g1_mesh_from(v, nv, t, nt);
    free(id);
    free(v);
    free(t);
    return m;
}

#endif /* FL_TEST_G1_MESHES_H */

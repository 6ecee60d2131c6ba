/* Closed genus-0 test meshes for the 3D flintstone tests: icospheres (optionally stretched into
 * an ellipsoid or radially perturbed), a subdivided cube (many coplanar vertices) and the
 * peanut reconstructed from data/demo/peanut.xyz. */
#ifndef HAL3_MESHES_H
#define HAL3_MESHES_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "flintstone.h"

static uint64_t hal3_rng = 88172645463325252ull;

static double hal3_rand(void) /* [0, 1) */
{
    hal3_rng ^= hal3_rng << 13;
    hal3_rng ^= hal3_rng >> 7;
    hal3_rng ^= hal3_rng << 17;
    return (double)(hal3_rng >> 11) / 9007199254740992.0;
}

/* Midpoint of edge (a, b), created once (linear search in a small per-vertex list). */
static uint32_t hal3_mid(fl_mesh *m, uint32_t *keys, uint32_t *vals, size_t cap, uint32_t a,
                         uint32_t b)
{
    if (a > b) {
        uint32_t t = a;
        a = b, b = t;
    }
    uint64_t key = ((uint64_t)a << 32) | b;
    size_t h = (size_t)((key * 11400714819323198485ull) >> 40) % cap;
    while (vals[h] != UINT32_MAX) {
        if (((uint64_t)keys[2 * h] << 32 | keys[2 * h + 1]) == key) return vals[h];
        h = (h + 1) % cap;
    }
    keys[2 * h] = a, keys[2 * h + 1] = b;
    uint32_t v = (uint32_t)m->vertex_count++;
    for (int k = 0; k < 3; k++) {
        double c = (m->xyz[3 * (size_t)a + k] + m->xyz[3 * (size_t)b + k]) / 2;
        m->xyz[3 * (size_t)v + k] = c;
    }
    double *p = m->xyz + 3 * (size_t)v, r = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (int k = 0; k < 3; k++)
        p[k] /= r;
    vals[h] = v;
    return v;
}

/* Unit icosphere with `levels` subdivisions (20 * 4^levels triangles), outward oriented. */
static fl_mesh hal3_icosphere(int levels)
{
    static const double X = 0.525731112119133606, Z = 0.850650808352039932;
    static const double v0[12][3] = {{-X, 0, Z}, {X, 0, Z},  {-X, 0, -Z}, {X, 0, -Z},
                                     {0, Z, X},  {0, Z, -X}, {0, -Z, X},  {0, -Z, -X},
                                     {Z, X, 0},  {-Z, X, 0}, {Z, -X, 0},  {-Z, -X, 0}};
    static const uint32_t t0[20][3] = {{0, 4, 1},  {0, 9, 4},  {9, 5, 4},  {4, 5, 8},  {4, 8, 1},
                                       {8, 10, 1}, {8, 3, 10}, {5, 3, 8},  {5, 2, 3},  {2, 7, 3},
                                       {7, 10, 3}, {7, 6, 10}, {7, 11, 6}, {11, 0, 6}, {0, 1, 6},
                                       {6, 1, 10}, {9, 0, 11}, {9, 11, 2}, {9, 2, 5},  {7, 2, 11}};
    size_t nt = 20;
    for (int l = 0; l < levels; l++)
        nt *= 4;
    fl_mesh m;
    m.xyz = malloc((nt / 2 + 2) * 3 * sizeof(double));
    m.tri = malloc(nt * 3 * sizeof(uint32_t));
    memcpy(m.xyz, v0, sizeof v0);
    memcpy(m.tri, t0, sizeof t0);
    m.vertex_count = 12;
    m.triangle_count = 20;
    for (int l = 0; l < levels; l++) {
        size_t cap = 6 * m.triangle_count + 7;
        uint32_t *keys = malloc(2 * cap * sizeof(uint32_t)), *vals = malloc(cap * sizeof(uint32_t));
        memset(vals, 0xff, cap * sizeof(uint32_t));
        uint32_t *nt4 = malloc(4 * 3 * m.triangle_count * sizeof(uint32_t));
        for (size_t t = 0; t < m.triangle_count; t++) {
            uint32_t a = m.tri[3 * t], b = m.tri[3 * t + 1], c = m.tri[3 * t + 2];
            uint32_t ab = hal3_mid(&m, keys, vals, cap, a, b),
                     bc = hal3_mid(&m, keys, vals, cap, b, c),
                     ca = hal3_mid(&m, keys, vals, cap, c, a);
            uint32_t q[12] = {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca};
            memcpy(nt4 + 12 * t, q, sizeof q);
        }
        m.triangle_count *= 4;
        memcpy(m.tri, nt4, 3 * m.triangle_count * sizeof(uint32_t));
        free(nt4);
        free(keys);
        free(vals);
    }
    return m;
}

/* Icosphere scaled by (sx, sy, sz) and each vertex moved radially by up to +-noise. */
static fl_mesh hal3_blob(int levels, double sx, double sy, double sz, double noise)
{
    fl_mesh m = hal3_icosphere(levels);
    for (size_t v = 0; v < m.vertex_count; v++) {
        double f = 1 + noise * (2 * hal3_rand() - 1);
        m.xyz[3 * v] *= sx * f, m.xyz[3 * v + 1] *= sy * f, m.xyz[3 * v + 2] *= sz * f;
    }
    return m;
}

/* The surface of [0, n]^3 on the integer grid, two triangles a unit square, outward. */
static fl_mesh hal3_cube(int n)
{
    size_t g = (size_t)n + 1;
    uint32_t *id = malloc(g * g * g * sizeof(uint32_t));
    memset(id, 0xff, g * g * g * sizeof(uint32_t));
    fl_mesh m;
    m.xyz = malloc(g * g * g * 3 * sizeof(double));
    m.tri = malloc(12 * (size_t)n * n * 3 * sizeof(uint32_t));
    m.vertex_count = m.triangle_count = 0;
    for (int ax = 0; ax < 3; ax++)
        for (int side = 0; side <= n; side += n)
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++) {
                    uint32_t q[4];
                    int uv[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
                    for (int c = 0; c < 4; c++) {
                        int p[3];
                        p[ax] = side, p[(ax + 1) % 3] = uv[c][0], p[(ax + 2) % 3] = uv[c][1];
                        size_t key = ((size_t)p[0] * g + (size_t)p[1]) * g + (size_t)p[2];
                        if (id[key] == UINT32_MAX) {
                            id[key] = (uint32_t)m.vertex_count++;
                            for (int k = 0; k < 3; k++)
                                m.xyz[3 * (size_t)id[key] + k] = p[k];
                        }
                        q[c] = id[key];
                    }
                    /* (u, v) x (v, w) points along +ax; outward at side n, inward at 0. */
                    int flip = side == 0;
                    uint32_t t[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
                    if (flip) {
                        uint32_t s = t[1];
                        t[1] = t[2], t[2] = s;
                        s = t[4], t[4] = t[5], t[5] = s;
                    }
                    memcpy(m.tri + 3 * m.triangle_count, t, sizeof t);
                    m.triangle_count += 2;
                }
    free(id);
    return m;
}

/* The peanut of data/demo reconstructed into a closed genus-0 mesh (0 triangles on failure). */
static fl_mesh hal3_peanut(void)
{
    fl_mesh m;
    memset(&m, 0, sizeof m);
    fl_points pts;
    fl_error err;
    if (fl_read_points(FL_SOURCE_DIR "/data/demo/peanut.xyz", &pts, &err) != FL_OK) return m;
    fl_reconstruction3 rec;
    if (fl_reconstruct3(pts.coords, pts.count, NULL, &rec, &err) == FL_OK) {
        m.vertex_count = pts.count;
        m.xyz = pts.coords;
        pts.coords = NULL;
        m.triangle_count = rec.triangle_count;
        m.tri = rec.tri;
        rec.tri = NULL;
        fl_reconstruction3_free(&rec);
    }
    fl_points_free(&pts);
    return m;
}

#endif /* HAL3_MESHES_H */

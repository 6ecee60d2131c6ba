/* Meshes with known properties, generated in closed form for the mesh tests. Each fixture
 * owns its arrays (free with fl_mesh_free). */
#ifndef FL_TEST_MESH_FIXTURES_H
#define FL_TEST_MESH_FIXTURES_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "flintstone.h"

static inline fl_mesh fx_mesh_alloc(size_t nv, size_t nt)
{
    fl_mesh m;
    m.vertex_count = nv;
    m.triangle_count = nt;
    m.xyz = calloc(nv ? 3 * nv : 1, sizeof(double));
    m.tri = calloc(nt ? 3 * nt : 1, sizeof(uint32_t));
    return m;
}

static inline fl_mesh fx_from_arrays(const double *xyz, size_t nv, const uint32_t *tri, size_t nt)
{
    fl_mesh m = fx_mesh_alloc(nv, nt);
    memcpy(m.xyz, xyz, 3 * nv * sizeof(double));
    memcpy(m.tri, tri, 3 * nt * sizeof(uint32_t));
    return m;
}

/* Unit cube [0,1]^3, 12 triangles counter-clockwise seen from outside. */
static inline fl_mesh fx_cube(double x0, double y0, double z0, double s)
{
    static const double corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    static const uint32_t tri[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7},
                                        {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                                        {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    fl_mesh m = fx_mesh_alloc(8, 12);
    for (int v = 0; v < 8; v++) {
        m.xyz[3 * v] = x0 + s * corner[v][0];
        m.xyz[3 * v + 1] = y0 + s * corner[v][1];
        m.xyz[3 * v + 2] = z0 + s * corner[v][2];
    }
    memcpy(m.tri, tri, sizeof tri);
    return m;
}

/* Regular-ish tetrahedron, outward oriented. */
static inline fl_mesh fx_tetrahedron(void)
{
    static const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    static const uint32_t tri[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return fx_from_arrays(xyz, 4, tri, 4);
}

/* Torus of radii R > r around the z axis, nu x nv quads split into two triangles each,
 * outward oriented (d/du x d/dv points out). Vertex (i, j) = i * nv + j. */
static inline fl_mesh fx_torus(double R, double r, size_t nu, size_t nv)
{
    const double pi = 3.14159265358979323846;
    fl_mesh m = fx_mesh_alloc(nu * nv, 2 * nu * nv);
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++) {
            double u = 2 * pi * (double)i / (double)nu, v = 2 * pi * (double)j / (double)nv;
            double *p = m.xyz + 3 * (i * nv + j);
            p[0] = (R + r * cos(v)) * cos(u);
            p[1] = (R + r * cos(v)) * sin(u);
            p[2] = r * sin(v);
        }
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++) {
            uint32_t a = (uint32_t)(i * nv + j), b = (uint32_t)(((i + 1) % nu) * nv + j);
            uint32_t c = (uint32_t)(((i + 1) % nu) * nv + (j + 1) % nv);
            uint32_t d = (uint32_t)(i * nv + (j + 1) % nv);
            uint32_t *t = m.tri + 6 * (i * nv + j);
            t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
        }
    return m;
}

/* Concatenates two meshes (indices of b shifted). Frees a and b. */
static inline fl_mesh fx_concat(fl_mesh a, fl_mesh b)
{
    fl_mesh m = fx_mesh_alloc(a.vertex_count + b.vertex_count, a.triangle_count + b.triangle_count);
    memcpy(m.xyz, a.xyz, 3 * a.vertex_count * sizeof(double));
    memcpy(m.xyz + 3 * a.vertex_count, b.xyz, 3 * b.vertex_count * sizeof(double));
    memcpy(m.tri, a.tri, 3 * a.triangle_count * sizeof(uint32_t));
    for (size_t i = 0; i < 3 * b.triangle_count; i++)
        m.tri[3 * a.triangle_count + i] = b.tri[i] + (uint32_t)a.vertex_count;
    fl_mesh_free(&a);
    fl_mesh_free(&b);
    return m;
}

/* Disc: a fan of n triangles around a centre, counter-clockwise seen from +z. */
static inline fl_mesh fx_disc(size_t n)
{
    const double pi = 3.14159265358979323846;
    fl_mesh m = fx_mesh_alloc(n + 1, n);
    for (size_t i = 0; i < n; i++) {
        m.xyz[3 * (i + 1)] = cos(2 * pi * (double)i / (double)n);
        m.xyz[3 * (i + 1) + 1] = sin(2 * pi * (double)i / (double)n);
        m.tri[3 * i] = 0;
        m.tri[3 * i + 1] = (uint32_t)(i + 1);
        m.tri[3 * i + 2] = (uint32_t)((i + 1) % n + 1);
    }
    return m;
}

#endif /* FL_TEST_MESH_FIXTURES_H */

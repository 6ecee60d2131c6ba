/* Generates the large synthetic inputs of the reading benchmarks with our own writer:
 *
 *   gen_mesh OUT NU NV
 *
 * writes a closed, consistently oriented torus of NU*NV vertices and 2*NU*NV triangles to OUT
 * (format by extension, fl_write_mesh: .ply binary little endian, .stl binary, .off, .obj).
 * 1000 x 1000 gives the 1M-vertex PLY, 1000 x 500 the 1M-triangle STL. The tube radius is
 * perturbed by a smooth ripple so that coordinates are not a regular lattice (a lattice would
 * flatter a reader whose number parsing or hashing likes repeated values); the ripple is small
 * enough that the surface stays embedded. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "flintstone.h"

static const double PI = 3.14159265358979323846;

/* Vertex (i, j) sits at angle u = 2*pi*i/nu around the axis and v = 2*pi*j/nv around the tube. */
static void torus_vertices(size_t nu, size_t nv, double *xyz)
{
    const double big = 3.0, small = 1.0;
    for (size_t i = 0; i < nu; i++) {
        double u = 2 * PI * (double)i / (double)nu;
        for (size_t j = 0; j < nv; j++) {
            double v = 2 * PI * (double)j / (double)nv;
            double r = small * (1 + 0.05 * sin(7 * u + 3 * v) * cos(5 * v));
            double *p = xyz + 3 * (i * nv + j);
            p[0] = (big + r * cos(v)) * cos(u);
            p[1] = (big + r * cos(v)) * sin(u);
            p[2] = r * sin(v);
        }
    }
}

/* Two triangles a grid cell. (d/du x d/dv) points out of the torus, so (i,j) -> (i+1,j) ->
 * (i+1,j+1) is counter-clockwise seen from outside. */
static void torus_triangles(size_t nu, size_t nv, uint32_t *tri)
{
    for (size_t i = 0; i < nu; i++) {
        for (size_t j = 0; j < nv; j++) {
            uint32_t a = (uint32_t)(i * nv + j);
            uint32_t b = (uint32_t)(((i + 1) % nu) * nv + j);
            uint32_t c = (uint32_t)(((i + 1) % nu) * nv + (j + 1) % nv);
            uint32_t d = (uint32_t)(i * nv + (j + 1) % nv);
            uint32_t *t = tri + 6 * (i * nv + j);
            t[0] = a, t[1] = b, t[2] = c;
            t[3] = a, t[4] = c, t[5] = d;
        }
    }
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: %s OUT NU NV\n", argv[0]);
        return 2;
    }
    long nu = strtol(argv[2], NULL, 10), nv = strtol(argv[3], NULL, 10);
    if (nu < 3 || nv < 3 || nu > 20000 || nv > 20000) {
        fprintf(stderr, "%s: NU and NV must be 3..20000\n", argv[0]);
        return 2;
    }
    fl_mesh mesh = {0};
    mesh.vertex_count = (size_t)nu * (size_t)nv;
    mesh.triangle_count = 2 * mesh.vertex_count;
    mesh.xyz = malloc(3 * mesh.vertex_count * sizeof *mesh.xyz);
    mesh.tri = malloc(3 * mesh.triangle_count * sizeof *mesh.tri);
    if (!mesh.xyz || !mesh.tri) {
        fprintf(stderr, "%s: out of memory\n", argv[0]);
        return 1;
    }
    torus_vertices((size_t)nu, (size_t)nv, mesh.xyz);
    torus_triangles((size_t)nu, (size_t)nv, mesh.tri);
    fl_error err;
    fl_status st = fl_write_mesh(argv[1], &mesh, &err);
    if (st != FL_OK) {
        char msg[1200];
        fl_error_format(&err, msg, sizeof msg);
        fprintf(stderr, "%s: %s\n", argv[0], msg);
    }
    free(mesh.xyz);
    free(mesh.tri);
    return st == FL_OK ? 0 : 1;
}

/* Brute-force point-in-polyhedron for the HAL3 tests, benchmark and fuzz target: on the surface
 * by exact predicates, else the parity of a +z ray over every triangle, with its own symbolic
 * perturbation (x moved by (e, e^2) in the xy-plane) so that rays through edges and vertices
 * count once. Independent of src/hal (which casts along other axes, through its tree). */
#ifndef HAL3_ORACLE_H
#define HAL3_ORACLE_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

/* Exactly whether x lies on the closed triangle abc. */
static inline int hal3_oracle_on_triangle(const double *a, const double *b, const double *c,
                                          const double *x)
{
    if (fl_orient3d(a, b, c, x) != 0) return 0;
    for (int ax = 0; ax < 3; ax++) {
        int i = (ax + 1) % 3, j = (ax + 2) % 3;
        double A[2] = {a[i], a[j]}, B[2] = {b[i], b[j]}, C[2] = {c[i], c[j]}, X[2] = {x[i], x[j]};
        int s = fl_orient2d(A, B, C);
        if (s)
            return fl_orient2d(A, B, X) * s >= 0 && fl_orient2d(B, C, X) * s >= 0 &&
                   fl_orient2d(C, A, X) * s >= 0;
    }
    return 0;
}

/* orient2d in the xy-plane of (a, b, x + (e, e^2)). */
static inline int hal3_oracle_pert(const double *a, const double *b, const double *x)
{
    double A[2] = {a[0], a[1]}, B[2] = {b[0], b[1]}, X[2] = {x[0], x[1]};
    int o = fl_orient2d(A, B, X);
    if (o) return o;
    if (A[1] != B[1]) return A[1] > B[1] ? 1 : -1;
    return B[0] > A[0] ? 1 : B[0] < A[0] ? -1 : 0;
}

/* 0 outside, 1 inside, 2 on the surface (the values of FL_HAL3_OUTSIDE / INSIDE / BOUNDARY). */
static inline uint8_t hal3_oracle_inside(const fl_mesh *m, const double *x)
{
    int parity = 0;
    for (size_t t = 0; t < m->triangle_count; t++) {
        const double *a = m->xyz + 3 * (size_t)m->tri[3 * t];
        const double *b = m->xyz + 3 * (size_t)m->tri[3 * t + 1];
        const double *c = m->xyz + 3 * (size_t)m->tri[3 * t + 2];
        if (hal3_oracle_on_triangle(a, b, c, x)) return 2;
        double A[2] = {a[0], a[1]}, B[2] = {b[0], b[1]}, C[2] = {c[0], c[1]};
        int s = fl_orient2d(A, B, C);
        if (!s || hal3_oracle_pert(a, b, x) != s || hal3_oracle_pert(b, c, x) != s ||
            hal3_oracle_pert(c, a, x) != s)
            continue;
        /* n_z has the sign s; x is below the plane (fl_orient3d > 0 means on the -n side) */
        parity ^= fl_orient3d(a, b, c, x) * s > 0;
    }
    return (uint8_t)parity;
}

#endif /* HAL3_ORACLE_H */

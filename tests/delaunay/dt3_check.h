/* Independent checks shared by the 3D triangulation tests: brute force with the exact
 * (unperturbed) predicates, nothing from src/delaunay. */
#ifndef DT3_CHECK_H
#define DT3_CHECK_H

#include <stdint.h>
#include <stdlib.h>

#include "flintstone.h"

/* Signed volume of the tetrahedron, positive for fl_orient3d > 0 (floating point). */
static inline double dt3c_volume(const double *a, const double *b, const double *c, const double *d)
{
    double m[3][3];
    for (int k = 0; k < 3; k++) {
        m[0][k] = a[k] - d[k];
        m[1][k] = b[k] - d[k];
        m[2][k] = c[k] - d[k];
    }
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) /
           6.0;
}

/* Number of (tetrahedron, point) pairs where the point is strictly inside the circumsphere
 * (weighted: strictly below the lifted hyperplane). O(T n). */
static inline size_t dt3c_empty_sphere_violations(const double *p, size_t stride, size_t n,
                                                  const uint32_t *tet, size_t nt, int weighted)
{
    size_t bad = 0;
    for (size_t t = 0; t < nt; t++) {
        const double *a = p + stride * tet[4 * t], *b = p + stride * tet[4 * t + 1],
                     *c = p + stride * tet[4 * t + 2], *d = p + stride * tet[4 * t + 3];
        for (size_t i = 0; i < n; i++) {
            int s = weighted ? fl_insphere_weighted(a, b, c, d, p + stride * i)
                             : fl_insphere(a, b, c, d, p + stride * i);
            bad += s > 0;
        }
    }
    return bad;
}

/* Is point i on the boundary of the convex hull of p[0..n)? Brute force over all triples:
 * some non-collinear triple spans a plane with every point on one side and i in it. O(n^4). */
static inline int dt3c_on_hull(const double *p, size_t stride, size_t n, size_t i)
{
    for (size_t a = 0; a < n; a++)
        for (size_t b = a + 1; b < n; b++)
            for (size_t c = b + 1; c < n; c++) {
                const double *A = p + stride * a, *B = p + stride * b, *C = p + stride * c;
                if (fl_orient3d(A, B, C, p + stride * i) != 0) continue;
                int pos = 0, neg = 0;
                for (size_t j = 0; j < n && !(pos && neg); j++) {
                    int s = fl_orient3d(A, B, C, p + stride * j);
                    pos |= s > 0;
                    neg |= s < 0;
                }
                if (pos != neg) /* one side only (and the triple is not collinear) */
                    return 1;
            }
    return 0;
}

#endif

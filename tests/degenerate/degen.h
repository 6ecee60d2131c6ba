/* Shared point-set generators and the error expectation of the degenerate-input suite. Every
 * generator builds its set from exactly representable values (integer grids, Pythagorean
 * points on circles and spheres, power-of-two scalings), so a degeneracy the case names is
 * really there, not approximately. */
#ifndef DEGEN_H
#define DEGEN_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "fl_test.h"

/* A failing call must return `expected` and a message containing `needle` (case-sensitive). */
#define CHECK_FAILS(st, errp, expected, needle)                                                    \
    do {                                                                                           \
        fl_status fl_st_ = (st);                                                                   \
        CHECK_MSG(fl_st_ == (expected), "status %d, expected %d (%s)", (int)fl_st_,              \
                  (int)(expected), (errp)->message);                                               \
        CHECK_MSG(strstr((errp)->message, (needle)) != NULL, "message '%s' lacks '%s'",          \
                  (errp)->message, (needle));                                                      \
    } while (0)

/* k x k integer grid in 2D (k*k points, xy). */
static inline size_t grid2(double *xy, int k, double scale)
{
    size_t n = 0;
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++) {
            xy[2 * n] = i * scale;
            xy[2 * n + 1] = j * scale;
            n++;
        }
    return n;
}

/* k x k x k integer grid in 3D. */
static inline size_t grid3(double *xyz, int k, double scale)
{
    size_t n = 0;
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++)
            for (int l = 0; l < k; l++) {
                xyz[3 * n] = i * scale, xyz[3 * n + 1] = j * scale, xyz[3 * n + 2] = l * scale;
                n++;
            }
    return n;
}

/* The 12 integer points on the circle x^2 + y^2 = 25, exactly cocircular, in angular order. */
static inline size_t circle12(double *xy, double scale)
{
    static const int p[12][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                 {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    for (int i = 0; i < 12; i++) xy[2 * i] = p[i][0] * scale, xy[2 * i + 1] = p[i][1] * scale;
    return 12;
}

/* The 30 integer points on the sphere x^2 + y^2 + z^2 = 9: (±3,0,0) and the permutations of
 * (±1,±2,±2). Exactly cospherical, with many cocircular (coplanar) quadruples. */
static inline size_t sphere30(double *xyz, double scale)
{
    size_t n = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int s = -1; s <= 1; s += 2) {
            double p[3] = {0, 0, 0};
            p[axis] = 3 * s;
            for (int c = 0; c < 3; c++) xyz[3 * n + c] = p[c] * scale;
            n++;
        }
    for (int one = 0; one < 3; one++)
        for (int m = 0; m < 8; m++) {
            double p[3];
            for (int c = 0, bit = 0; c < 3; c++) {
                double v = c == one ? 1 : 2;
                p[c] = ((m >> bit++) & 1) ? -v : v;
            }
            for (int c = 0; c < 3; c++) xyz[3 * n + c] = p[c] * scale;
            n++;
        }
    return n;
}

#endif

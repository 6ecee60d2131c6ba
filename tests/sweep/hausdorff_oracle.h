/* Independent checks for the Hausdorff tests: brute-force point-to-mesh distances (long double,
 * sweep_oracle.h, no code shared with src/sweep) and dense sampling of a mesh's triangles on a
 * barycentric grid. The dense maximum is a lower estimate of the directed Hausdorff distance;
 * since d(., B) is 1-Lipschitz it is also within the grid spacing of the true value. */
#ifndef HAUSDORFF_ORACLE_H
#define HAUSDORFF_ORACLE_H

#include <stdlib.h>
#include <time.h>

#include "fl_test.h"
#include "sweep_oracle.h"

/* Wall-clock seconds (C11 timespec_get). */
static inline double hd_test_now(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static inline double oracle_mesh_distance(const fl_mesh *m, const double *p)
{
    ld best = 1e300L;
    for (size_t t = 0; t < m->triangle_count; t++) {
        ld d = oracle_mesh_element(m->xyz, m->tri, t, p);
        if (d < best) best = d;
    }
    return (double)best;
}

/* Dense directed distance: the largest brute-force distance to b over an n-step barycentric
 * grid on every triangle of a. *spacing receives the largest grid step (longest edge / n). */
static inline double oracle_dense_directed(const fl_mesh *a, const fl_mesh *b, int n,
                                           double *spacing)
{
    double best = 0, step = 0;
    for (size_t t = 0; t < a->triangle_count; t++) {
        const double *v[3];
        for (int k = 0; k < 3; k++)
            v[k] = a->xyz + 3 * (size_t)a->tri[3 * t + (size_t)k];
        for (int k = 0; k < 3; k++) {
            double e = 0;
            for (int x = 0; x < 3; x++)
                e += (v[k][x] - v[(k + 1) % 3][x]) * (v[k][x] - v[(k + 1) % 3][x]);
            step = fmax(step, sqrt(e) / n);
        }
        for (int i = 0; i <= n; i++)
            for (int j = 0; i + j <= n; j++) {
                double l0 = (double)i / n, l1 = (double)j / n, l2 = 1 - l0 - l1, p[3];
                for (int x = 0; x < 3; x++)
                    p[x] = l0 * v[0][x] + l1 * v[1][x] + l2 * v[2][x];
                best = fmax(best, oracle_mesh_distance(b, p));
            }
    }
    if (spacing) *spacing = step;
    return best;
}

static inline fl_mesh oracle_mesh_alloc(size_t nv, size_t nt)
{
    fl_mesh m = {nv, calloc(3 * nv, sizeof(double)), nt, calloc(3 * nt, sizeof(uint32_t))};
    return m;
}

/* A flat n x n grid of squares (2 n^2 triangles) over [x0, x0+1] x [y0, y0+1] at height z. */
static inline fl_mesh oracle_grid(int n, double x0, double y0, double z)
{
    fl_mesh m = oracle_mesh_alloc((size_t)(n + 1) * (n + 1), 2 * (size_t)n * n);
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) {
            double *p = m.xyz + 3 * ((size_t)i * (n + 1) + j);
            p[0] = x0 + (double)i / n, p[1] = y0 + (double)j / n, p[2] = z;
        }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            uint32_t a = (uint32_t)(i * (n + 1) + j), b = a + (uint32_t)(n + 1);
            uint32_t *t = m.tri + 6 * ((size_t)i * n + j);
            t[0] = a, t[1] = b, t[2] = b + 1, t[3] = a, t[4] = b + 1, t[5] = a + 1;
        }
    return m;
}

/* The axis-aligned cube [-1,1]^3 as 12 triangles, rotated by angle about the axis (1,2,3)/|.|
 * and translated by t. */
static inline fl_mesh oracle_cube(double angle, const double *t)
{
    static const uint32_t faces[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                       2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
    fl_mesh m = oracle_mesh_alloc(8, 12);
    double ax[3] = {1 / sqrt(14.0), 2 / sqrt(14.0), 3 / sqrt(14.0)};
    double c = cos(angle), s = sin(angle);
    for (int v = 0; v < 8; v++) {
        double p[3] = {(v & 1) ^ ((v >> 1) & 1) ? 1 : -1, (v & 2) ? 1 : -1, (v & 4) ? 1 : -1};
        double d = ax[0] * p[0] + ax[1] * p[1] + ax[2] * p[2];
        double cr[3] = {ax[1] * p[2] - ax[2] * p[1], ax[2] * p[0] - ax[0] * p[2],
                        ax[0] * p[1] - ax[1] * p[0]};
        for (int x = 0; x < 3; x++) /* Rodrigues */
            m.xyz[3 * v + x] = p[x] * c + cr[x] * s + ax[x] * d * (1 - c) + t[x];
    }
    memcpy(m.tri, faces, sizeof faces);
    return m;
}

/* Checks the certificate of a result against dense sampling: the interval contains the dense
 * value (lower estimate of the truth) up to rounding, `upper` is within the grid spacing plus
 * the precision of it when not budget-limited, and the lower bound is a real distance measured
 * at a point of the shape (where[0] on A or B, brute-force distance = lower up to slack). */
static inline void oracle_check_certificate(const fl_mesh *a, const fl_mesh *b,
                                            const fl_hausdorff_result *r, int grid,
                                            int expect_precision)
{
    double sa, sb;
    double dab = oracle_dense_directed(a, b, grid, &sa);
    double dba = oracle_dense_directed(b, a, grid, &sb);
    double tiny = 1e-12;
    CHECK_MSG(r->h_ab[0] <= r->h_ab[1] && r->h_ba[0] <= r->h_ba[1], "ordered intervals");
    CHECK_MSG(dab <= r->h_ab[1] + tiny, "dense h_ab %.17g above upper %.17g", dab, r->h_ab[1]);
    CHECK_MSG(dba <= r->h_ba[1] + tiny, "dense h_ba %.17g above upper %.17g", dba, r->h_ba[1]);
    CHECK_MSG(r->h_ab[0] <= dab + sa + tiny, "h_ab lower %.17g above dense %.17g + spacing",
              r->h_ab[0], dab);
    CHECK_MSG(r->h_ba[0] <= dba + sb + tiny, "h_ba lower %.17g above dense %.17g + spacing",
              r->h_ba[0], dba);
    const fl_mesh *on = r->where_on_b ? b : a, *other = r->where_on_b ? a : b;
    CHECK_MSG(oracle_mesh_distance(on, r->where[0]) <= 1e-12, "where[0] lies on its shape");
    CHECK_NEAR(oracle_mesh_distance(other, r->where[0]), r->hausdorff[0], 1e-12);
    if (expect_precision) {
        CHECK(!r->budget_exhausted);
        CHECK_MSG(r->hausdorff[1] - r->hausdorff[0] <= r->precision, "width %.3g > %.3g",
                  r->hausdorff[1] - r->hausdorff[0], r->precision);
        CHECK_MSG(r->hausdorff[1] <= fmax(dab + sa, dba + sb) + r->precision + tiny,
                  "upper %.17g not within spacing + precision of dense", r->hausdorff[1]);
    }
}

#endif /* HAUSDORFF_ORACLE_H */

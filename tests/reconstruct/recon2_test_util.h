/* Shapes with a known boundary order and independent checks of a 2D reconstruction: simplicity
 * through fl_polygon_check, exact coverage of the polygon by the interior triangles (areas by
 * the shoelace formula, orientation by fl_orient2d), and the cyclic order compared with the
 * curve the points were sampled from. */
#ifndef RECON2_TEST_UTIL_H
#define RECON2_TEST_UTIL_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"

#define RT_PI 3.14159265358979323846

/* n points on the closed curve r(t) = 1 + amp * cos(lobes * t) (a star-like shape for amp > 0),
 * equally spaced in t, counterclockwise. */
static inline double *rt_star(size_t n, int lobes, double amp)
{
    double *xy = malloc(2 * n * sizeof *xy);
    for (size_t i = 0; i < n; i++) {
        double t = 2 * RT_PI * (double)i / (double)n, r = 1 + amp * cos(lobes * t);
        xy[2 * i] = r * cos(t);
        xy[2 * i + 1] = r * sin(t);
    }
    return xy;
}

/* n points along a closed polygon (corners[2k], corners[2k+1], k < m, counterclockwise), equally
 * spaced by arc length starting at corner 0; every corner is a sample. */
static inline double *rt_polygon(const double *corners, size_t m, size_t per_unit, size_t *n_out)
{
    size_t n = 0;
    for (size_t k = 0; k < m; k++) {
        const double *p = corners + 2 * k, *q = corners + 2 * ((k + 1) % m);
        n += (size_t)ceil(hypot(q[0] - p[0], q[1] - p[1]) * (double)per_unit);
    }
    double *xy = malloc(2 * n * sizeof *xy);
    size_t j = 0;
    for (size_t k = 0; k < m; k++) {
        const double *p = corners + 2 * k, *q = corners + 2 * ((k + 1) % m);
        size_t s = (size_t)ceil(hypot(q[0] - p[0], q[1] - p[1]) * (double)per_unit);
        for (size_t i = 0; i < s; i++) {
            double f = (double)i / (double)s;
            xy[2 * j] = p[0] + f * (q[0] - p[0]);
            xy[2 * j + 1] = p[1] + f * (q[1] - p[1]);
            j++;
        }
    }
    *n_out = n;
    return xy;
}

/* 1 when rec->boundary is the cycle 0, 1, ..., n-1 up to rotation. */
static inline int rt_is_input_order(const fl_reconstruction2 *rec, size_t n)
{
    if (rec->boundary_count != n) return 0;
    size_t s = rec->boundary[0];
    for (size_t i = 0; i < n; i++)
        if (rec->boundary[i] != (s + i) % n) return 0;
    return 1;
}

/* 1 when x and y hold the same cycle of m vertices (the same direction, any starting point). */
static inline int rt_same_cycle(const uint32_t *x, const uint32_t *y, size_t m)
{
    size_t s = 0;
    while (s < m && y[s] != x[0])
        s++;
    if (s == m) return m == 0;
    for (size_t i = 0; i < m; i++)
        if (x[i] != y[(s + i) % m]) return 0;
    return 1;
}

/* Checks the invariants every result must satisfy: the boundary is a simple counterclockwise
 * polygon of distinct vertices (fl_polygon_check), the interior triangles are counterclockwise,
 * use only boundary vertices or points left inside, and their areas add up to the polygon's
 * area; with all_on_boundary, there are boundary_count - 2 of them. */
static inline void rt_check_valid(const double *xy, const fl_reconstruction2 *rec)
{
    size_t m = rec->boundary_count;
    CHECK(m >= 3);
    fl_polygon pg = {m, malloc(2 * m * sizeof(double)), 1, (size_t[]){0, m}, 1, (size_t[]){0, 1}};
    for (size_t i = 0; i < m; i++) {
        pg.xy[2 * i] = xy[2 * (size_t)rec->boundary[i]];
        pg.xy[2 * i + 1] = xy[2 * (size_t)rec->boundary[i] + 1];
    }
    fl_polygon_report rep;
    fl_error err;
    CHECK_STATUS(fl_polygon_check(&pg, &rep, &err), FL_OK, &err);
    CHECK_MSG(rep.simple == 1, "%zu edge intersections", rep.edge_intersections);
    CHECK_EQ_INT(rep.ring_orientation[0], 1);
    double tri_area = 0;
    for (size_t t = 0; t < rec->triangle_count; t++) {
        const uint32_t *c = rec->tri + 3 * t;
        const double *a = xy + 2 * (size_t)c[0], *b = xy + 2 * (size_t)c[1],
                     *d = xy + 2 * (size_t)c[2];
        CHECK(fl_orient2d(a, b, d) > 0);
        tri_area += ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0])) / 2;
    }
    CHECK_NEAR(tri_area, rep.area, 1e-9 * (1 + fabs(rep.area)));
    CHECK_NEAR(rec->area, rep.area, 1e-9 * (1 + fabs(rep.area)));
    if (rec->all_on_boundary) {
        CHECK_EQ_INT(rec->triangle_count, m - 2);
        CHECK_EQ_INT(m, rec->unique_count);
        CHECK(rec->reason[0] == 0);
    } else {
        CHECK(rec->reason[0] != 0);
        CHECK_EQ_INT(rec->triangle_count, m - 2 + 2 * (rec->unique_count - m));
    }
    fl_polygon_report_free(&rep);
    free(pg.xy);
}

#endif /* RECON2_TEST_UTIL_H */

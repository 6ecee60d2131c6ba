/* Known scenes for the renderer tests and an independent count of the pixel centres inside a
 * convex silhouette (hull of projected points, decided with the exact orientation test). */
#ifndef RENDER_SCENES_H
#define RENDER_SCENES_H

#include "fl_test.h"

#define PI 3.14159265358979323846
#define SQRT1_2 0.70710678118654752440

/* The unit cube [0,1]^3 as 12 triangles, counter-clockwise seen from outside. */
static const double cube_xyz[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                    0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
static const uint32_t cube_tri[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                      1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

static inline fl_mesh cube_mesh(void)
{
    fl_mesh m = {8, (double *)cube_xyz, 12, (uint32_t *)cube_tri};
    return m;
}

/* Convex hull (counter-clockwise in a y-up frame: we negate pixel y) of n points, by Andrew's
 * monotone chain with exact orientation; returns the hull size, hull[] receives indices. */
static inline size_t hull2(const double (*p)[2], size_t n, size_t *hull)
{
    size_t idx[64], k = 0;
    for (size_t i = 0; i < n; i++)
        idx[i] = i;
    for (size_t i = 1; i < n; i++) /* insertion sort by (x, y) */
        for (size_t j = i;
             j > 0 && (p[idx[j]][0] < p[idx[j - 1]][0] ||
                       (p[idx[j]][0] == p[idx[j - 1]][0] && p[idx[j]][1] < p[idx[j - 1]][1]));
             j--) {
            size_t t = idx[j];
            idx[j] = idx[j - 1];
            idx[j - 1] = t;
        }
    for (int pass = 0; pass < 2; pass++) {
        size_t start = k;
        for (size_t ii = 0; ii < n; ii++) {
            size_t i = pass ? idx[n - 1 - ii] : idx[ii];
            while (k >= start + 2 && fl_orient2d(p[hull[k - 2]], p[hull[k - 1]], p[i]) <= 0)
                k--;
            hull[k++] = i;
        }
        k--; /* the last point starts the other chain */
    }
    return k;
}

/* Counts pixel centres (i + 0.5, j + 0.5) of a w x h image whose signed distance to the hull of
 * the projected points is > margin (inside by margin; margin < 0 counts a slightly grown
 * hull). Points are in pixel coordinates (y down). */
static inline size_t count_inside(const double (*px)[2], size_t n, uint32_t w, uint32_t h,
                                  double margin)
{
    double p[64][2];
    size_t hull[130];
    for (size_t i = 0; i < n; i++) {
        p[i][0] = px[i][0];
        p[i][1] = -px[i][1];
    }
    size_t m = hull2((const double(*)[2])p, n, hull), count = 0;
    for (uint32_t j = 0; j < h; j++)
        for (uint32_t i = 0; i < w; i++) {
            double q[2] = {i + 0.5, -(j + 0.5)}, dmin = INFINITY;
            for (size_t e = 0; e < m; e++) {
                const double *a = p[hull[e]], *b = p[hull[(e + 1) % m]];
                double ex = b[0] - a[0], ey = b[1] - a[1];
                double d = (ex * (q[1] - a[1]) - ey * (q[0] - a[0])) / hypot(ex, ey);
                dmin = fmin(dmin, d);
            }
            count += dmin > margin;
        }
    return count;
}

static inline size_t count_color(const fl_image *img, const uint8_t rgba[4])
{
    size_t n = 0;
    for (size_t i = 0; i < (size_t)img->width * img->height; i++)
        n += memcmp(img->rgba + 4 * i, rgba, 4) == 0;
    return n;
}

#endif

/* Independent oracles for the 2D Delaunay tests: brute-force empty circle and Andrew's monotone
 * chain hull, both with the exact predicates only. */
#ifndef DT2_TEST_UTIL_H
#define DT2_TEST_UTIL_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"

static inline const double *tu_pt(const double *xy, uint32_t i)
{
    return xy + 2 * (size_t)i;
}

/* Number of (triangle, distinct point) pairs with the point strictly inside the circumcircle. */
static inline size_t tu_empty_circle_violations(const double *xy, const fl_dt2 *dt)
{
    size_t bad = 0;
    for (size_t t = 0; t < dt->triangle_count; t++) {
        const uint32_t *v = dt->tri + 3 * t;
        for (size_t i = 0; i < dt->point_count; i++) {
            if (dt->duplicate_of[i] != i) continue;
            bad += fl_incircle(tu_pt(xy, v[0]), tu_pt(xy, v[1]), tu_pt(xy, v[2]),
                               tu_pt(xy, (uint32_t)i)) > 0;
        }
    }
    return bad;
}

static const double *tu_sort_xy;
static inline int tu_lex_cmp(const void *a, const void *b)
{
    const double *p = tu_pt(tu_sort_xy, *(const uint32_t *)a),
                 *q = tu_pt(tu_sort_xy, *(const uint32_t *)b);
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    if (p[1] != q[1]) return p[1] < q[1] ? -1 : 1;
    return 0;
}

static const double *tu_edge_a, *tu_edge_b; /* edge being filled, for tu_along_cmp */
static inline int tu_along_cmp(const void *x, const void *y)
{
    int k = tu_edge_a[0] != tu_edge_b[0] ? 0 : 1;
    double s = tu_edge_a[k] < tu_edge_b[k] ? 1.0 : -1.0;
    double p = s * tu_pt(tu_sort_xy, *(const uint32_t *)x)[k];
    double q = s * tu_pt(tu_sort_xy, *(const uint32_t *)y)[k];
    return p < q ? -1 : p > q;
}

/* Convex hull of the distinct points, counterclockwise, including points in the relative
 * interior of hull edges: Andrew's monotone chain for the corners (pop on left turns only),
 * then every point on each corner-to-corner edge, sorted along it. Returns the vertex count. */
static inline size_t tu_monotone_chain(const double *xy, const fl_dt2 *dt, uint32_t *hull)
{
    size_t m = 0, k = 0, h = 0;
    uint32_t *p = malloc(dt->unique_count * sizeof *p);
    uint32_t *corner = malloc((dt->unique_count + 1) * sizeof *corner);
    for (size_t i = 0; i < dt->point_count; i++)
        if (dt->duplicate_of[i] == i) p[m++] = (uint32_t)i;
    tu_sort_xy = xy;
    qsort(p, m, sizeof *p, tu_lex_cmp);
    for (size_t i = 0; i < m; i++) { /* lower hull */
        while (k >= 2 && fl_orient2d(tu_pt(xy, corner[k - 2]), tu_pt(xy, corner[k - 1]),
                                     tu_pt(xy, p[i])) <= 0)
            k--;
        corner[k++] = p[i];
    }
    for (size_t i = m - 1, lower = k + 1; i-- > 0;) { /* upper hull */
        while (k >= lower && fl_orient2d(tu_pt(xy, corner[k - 2]), tu_pt(xy, corner[k - 1]),
                                         tu_pt(xy, p[i])) <= 0)
            k--;
        corner[k++] = p[i];
    }
    for (size_t c = 0; c + 1 < k; c++) { /* corner[k - 1] repeats corner[0] */
        const double *a = tu_pt(xy, corner[c]), *b = tu_pt(xy, corner[c + 1]);
        size_t first = ++h;
        hull[first - 1] = corner[c];
        for (size_t i = 0; i < m; i++) {
            const double *q = tu_pt(xy, p[i]);
            int kk = a[0] != b[0] ? 0 : 1;
            if (fl_orient2d(a, b, q) == 0 &&
                ((a[kk] < q[kk] && q[kk] < b[kk]) || (b[kk] < q[kk] && q[kk] < a[kk])))
                hull[h++] = p[i];
        }
        tu_edge_a = a;
        tu_edge_b = b;
        qsort(hull + first, h - first, sizeof *hull, tu_along_cmp);
    }
    free(corner);
    free(p);
    return h;
}

/* The hull of dt equals the monotone-chain hull as a cyclic sequence. */
static inline int tu_hull_matches(const double *xy, const fl_dt2 *dt)
{
    uint32_t *ref = malloc(dt->unique_count * sizeof *ref);
    size_t h = tu_monotone_chain(xy, dt, ref), start = 0;
    int ok = h == dt->hull_count;
    while (ok && start < h && dt->hull[start] != ref[0])
        start++;
    for (size_t i = 0; ok && i < h; i++)
        ok = start < h && dt->hull[(start + i) % h] == ref[i];
    free(ref);
    return ok;
}

/* Builds, verifies and checks against the oracles (brute force only when brute != 0). */
static inline void tu_check_delaunay(const char *what, const double *xy, size_t n, int brute)
{
    fl_dt2 dt;
    fl_error err;
    fl_status st = fl_dt2_build(xy, n, NULL, &dt, &err);
    CHECK_MSG(st == FL_OK, "%s: build failed: %s", what, err.message);
    if (st != FL_OK) return;
    st = fl_dt2_verify(xy, &dt, &err);
    CHECK_MSG(st == FL_OK, "%s: verify failed: %s", what, err.message);
    CHECK_MSG(tu_hull_matches(xy, &dt), "%s: hull differs from monotone chain", what);
    CHECK_EQ_INT(dt.triangle_count, 2 * dt.unique_count - 2 - dt.hull_count);
    if (brute) CHECK_EQ_INT(tu_empty_circle_violations(xy, &dt), 0);
    fl_dt2_free(&dt);
}

#endif /* DT2_TEST_UTIL_H */

/* Independent check of a 2D Delaunay triangulation with the exact predicates.
 *
 * Why these checks suffice: if every triangle is counterclockwise with nonzero area, adjacency
 * is symmetric (each glued edge appears in opposite directions, so the two triangles lie on
 * opposite sides of it) and the unpaired edges form one simple convex counterclockwise cycle,
 * then the triangles, glued along the adjacency, map to the plane with degree equal to the
 * winding number of that cycle, 1: they cover its interior exactly once. With every distinct
 * point a vertex this is a triangulation of the point set; with every interior edge locally
 * Delaunay it is Delaunay (Delaunay's lemma, valid on a convex domain). */
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_internal.h"

#define NONE UINT32_MAX

#define FAIL(...) fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, __VA_ARGS__)

static const double *pt(const double *xy, uint32_t i)
{
    return xy + 2 * (size_t)i;
}

static fl_status check_duplicates(const double *xy, const fl_dt2 *dt, fl_error *err)
{
    uint32_t *rep = fl_alloc_array(dt->point_count, sizeof *rep);
    size_t unique = 0;
    if (!rep && dt->point_count)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory to verify the triangulation");
    fl_status st = fl_dt_unique(xy, dt->point_count, 2, rep, &unique, err);
    for (size_t i = 0; st == FL_OK && i < dt->point_count; i++)
        if (dt->duplicate_of[i] != rep[i])
            st = FAIL("duplicate_of[%zu] is %u, but the first point equal to point %zu is %u", i,
                      (unsigned)dt->duplicate_of[i], i, (unsigned)rep[i]);
    if (st == FL_OK && unique != dt->unique_count)
        st = FAIL("unique_count is %zu, but there are %zu distinct points", dt->unique_count,
                  unique);
    free(rep);
    return st;
}

/* Corner of triangle u whose opposite edge is b -> a, or -1. */
static int edge_in(const uint32_t *tri, uint32_t u, uint32_t a, uint32_t b)
{
    for (int j = 0; j < 3; j++)
        if (tri[3 * (size_t)u + (j + 1) % 3] == b && tri[3 * (size_t)u + (j + 2) % 3] == a)
            return j;
    return -1;
}

static fl_status check_triangles(const double *xy, const fl_dt2 *dt, fl_error *err)
{
    for (size_t t = 0; t < dt->triangle_count; t++) {
        const uint32_t *v = dt->tri + 3 * t;
        for (int k = 0; k < 3; k++) {
            if (v[k] >= dt->point_count)
                return FAIL("triangle %zu has vertex %u out of range", t, (unsigned)v[k]);
            if (dt->duplicate_of[v[k]] != v[k])
                return FAIL("triangle %zu uses point %u, a duplicate of point %u", t,
                            (unsigned)v[k], (unsigned)dt->duplicate_of[v[k]]);
        }
        if (fl_orient2d(pt(xy, v[0]), pt(xy, v[1]), pt(xy, v[2])) <= 0)
            return FAIL("triangle %zu (points %u, %u, %u) is not counterclockwise", t,
                        (unsigned)v[0], (unsigned)v[1], (unsigned)v[2]);
    }
    return FL_OK;
}

/* Adjacency symmetry and the empty-circle test at each interior edge (once per edge). */
static fl_status check_adjacency(const double *xy, const fl_dt2 *dt, size_t *boundary_edges,
                                 fl_error *err)
{
    *boundary_edges = 0;
    for (size_t t = 0; t < dt->triangle_count; t++) {
        const uint32_t *v = dt->tri + 3 * t;
        for (int k = 0; k < 3; k++) {
            uint32_t u = dt->adj[3 * t + k], a = v[(k + 1) % 3], b = v[(k + 2) % 3];
            if (u == NONE) {
                (*boundary_edges)++;
                continue;
            }
            int j = u < dt->triangle_count ? edge_in(dt->tri, u, a, b) : -1;
            if (j < 0 || dt->adj[3 * (size_t)u + j] != t)
                return FAIL("adjacency of triangles %zu and %u across edge %u-%u is not "
                            "symmetric",
                            t, (unsigned)u, (unsigned)a, (unsigned)b);
            if (u < t) continue;
            uint32_t d = dt->tri[3 * (size_t)u + j];
            const double *pa = pt(xy, v[0]), *pb = pt(xy, v[1]), *pc = pt(xy, v[2]);
            if (fl_incircle(pa, pb, pc, pt(xy, d)) > 0 ||
                fl_incircle_sos(pa, pb, pc, pt(xy, d), v[0], v[1], v[2], d) > 0)
                return FAIL("point %u is inside the circumcircle of triangle %zu (points %u, "
                            "%u, %u): not Delaunay",
                            (unsigned)d, t, (unsigned)v[0], (unsigned)v[1], (unsigned)v[2]);
        }
    }
    return FL_OK;
}

/* p strictly between a and b, for collinear a, p, b. */
static int strictly_between(const double *a, const double *b, const double *p)
{
    int k = a[0] != b[0] ? 0 : 1;
    return (a[k] < p[k] && p[k] < b[k]) || (b[k] < p[k] && p[k] < a[k]);
}

static int lex_less(const double *p, const double *q)
{
    return p[1] < q[1] || (p[1] == q[1] && p[0] < q[0]);
}

/* The hull cycle: left turns or straight-through vertices, winding once (a single
 * lexicographic minimum; a polygon turning left that winds k times has k of them). */
static fl_status check_hull_convex(const double *xy, const fl_dt2 *dt, fl_error *err)
{
    size_t h = dt->hull_count, minima = 0;
    for (size_t i = 0; i < h; i++) {
        const double *p = pt(xy, dt->hull[(i + h - 1) % h]), *q = pt(xy, dt->hull[i]),
                     *r = pt(xy, dt->hull[(i + 1) % h]);
        int o = fl_orient2d(p, q, r);
        if (o < 0 || (o == 0 && !strictly_between(p, r, q)))
            return FAIL("the hull turns right or back at point %u", (unsigned)dt->hull[i]);
        minima += lex_less(q, p) && lex_less(q, r);
    }
    if (minima != 1) return FAIL("the hull winds %zu times around its interior", minima);
    return FL_OK;
}

/* The unpaired triangle edges are exactly the hull edges, each once, in the hull's order. */
static fl_status check_hull_is_boundary(const fl_dt2 *dt, size_t boundary_edges, fl_error *err)
{
    if (dt->hull_count < 3 || boundary_edges != dt->hull_count)
        return FAIL("%zu boundary edges but %zu hull vertices", boundary_edges, dt->hull_count);
    uint32_t *next = fl_alloc_array(dt->point_count, sizeof *next);
    if (!next) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory to verify the hull");
    memset(next, 0xFF, dt->point_count * sizeof *next);
    fl_status st = FL_OK;
    for (size_t t = 0; t < dt->triangle_count && st == FL_OK; t++)
        for (int k = 0; k < 3 && st == FL_OK; k++) {
            if (dt->adj[3 * t + k] != NONE) continue;
            uint32_t a = dt->tri[3 * t + (k + 1) % 3], b = dt->tri[3 * t + (k + 2) % 3];
            if (next[a] != NONE) st = FAIL("two boundary edges start at point %u", (unsigned)a);
            next[a] = b;
        }
    for (size_t i = 0; i < dt->hull_count && st == FL_OK; i++) {
        uint32_t a = dt->hull[i], b = dt->hull[(i + 1) % dt->hull_count];
        if (a >= dt->point_count || next[a] != b)
            st = FAIL("hull edge %u-%u is not a boundary edge of the triangles", (unsigned)a,
                      (unsigned)b);
    }
    free(next);
    return st;
}

/* Euler's relation for a disk, V - E + F = 1, with V the distinct points (all must be used). */
static fl_status check_euler(const fl_dt2 *dt, size_t boundary_edges, fl_error *err)
{
    unsigned char *used = calloc(dt->point_count ? dt->point_count : 1, 1);
    if (!used) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory to verify the vertices");
    size_t v = 0;
    for (size_t i = 0; i < 3 * dt->triangle_count; i++)
        if (!used[dt->tri[i]]) {
            used[dt->tri[i]] = 1;
            v++;
        }
    free(used);
    if (v != dt->unique_count)
        return FAIL("%zu of the %zu distinct points are triangle vertices", v, dt->unique_count);
    size_t e = (3 * dt->triangle_count + boundary_edges) / 2, f = dt->triangle_count;
    if (v + f != e + 1) return FAIL("Euler relation V - E + F = 1 fails: %zu - %zu + %zu", v, e, f);
    return FL_OK;
}

fl_status fl_dt2_verify(const double *xy, const fl_dt2 *dt, fl_error *err)
{
    if (!dt || (dt->point_count && (!xy || !dt->duplicate_of)) ||
        (dt->triangle_count && (!dt->tri || !dt->adj)) || (dt->hull_count && !dt->hull))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_dt2_verify: NULL buffer");
    size_t boundary_edges = 0;
    fl_status st = check_duplicates(xy, dt, err);
    if (st == FL_OK) st = check_triangles(xy, dt, err);
    if (st == FL_OK) st = check_adjacency(xy, dt, &boundary_edges, err);
    if (st == FL_OK) st = check_hull_is_boundary(dt, boundary_edges, err);
    if (st == FL_OK) st = check_hull_convex(xy, dt, err);
    if (st == FL_OK) st = check_euler(dt, boundary_edges, err);
    return st;
}

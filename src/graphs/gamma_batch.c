/* The largest empty neighbourhoods (Def. 3.3) of many given simplices against one point set,
 * each from the points near it instead of all N (fl_gamma_simplices_params).
 *
 * fl_gamma_simplex_params scans every point: O(N) a simplex, which made the augmented_c0 report
 * of 3D constriction O(N) per unlocking flip (docs/reconstruct3d.md). Here the points sit in one
 * bucket grid and each simplex visits them in rings of cells around the centre of its smallest
 * ball, nearest first, until every point that could still change its summary has been seen:
 *  - a point on the + side that would replace the witness `up` lies strictly inside the ball
 *    B(tau(up)) (the balls through the vertices are nested on each side, gamma_internal.h), and
 *    B(t) lies within |t| + sqrt(r^2 + t^2) of the centre; the same for `lo` on the - side;
 *  - a point on H that blocks lies in the closed smallest ball, within r of the centre;
 *  - while a side has no witness yet, any point there could become one: the scan goes on (to
 *    the whole grid if that side is empty, as for simplices on the convex hull).
 * The summary is a function of the set of points added (ties go to the smaller index), so the
 * result is the brute force's bit for bit; tests/graphs/test_gamma_batch.c compares them.
 * The floating centre, radius and offsets only decide when to stop; a relative margin of 1e-6
 * on the radius covers their rounding (as in gamma_triangles.c).
 *
 * That prunes only where the witnesses are near. A triangle between points sampled from a
 * surface, lying nearly in the surface, has its witness balls spanning the whole object
 * (c1' close to -1) and still costs O(N). fl_gamma_simplices_min_c1 wants only the smallest c1'
 * (what 3D constriction reports as augmented_c0) and avoids most such scans. While the minimum m
so far is >= 0 (every simplex seen is Delaunay: a flip of a nearly cospherical configuration
gives such triangles, 12 000 of them for 3e6 points on a surface, each scan O(N) before), a
simplex matters only if c1' < m, which needs both balls of magnitude m touching its vertices,
B(t_m) and B(-t_m), to hold a point; near-flat surface triangles have them close to their
smallest ball, so a box query settles it (side_ball_empty). Once some simplex
 * has c1' = m < 0, another one matters only if c1' < m, i.e. (Lemma 3.2) if a point lies in the
 * symmetric lens N_γ(m, m) = B(-T) ∩ B(T), T = r sqrt(g^2 - 1), g = 1/(1 + m), which lies inside
 * the smallest ball: a point q with d = q - centre and h = d.normal is in it iff
 * |d|^2 + 2T|h| < r^2. Points farther than r from the centre are never in it, so a box query
 * decides; only simplices that pass get the exact scan, and the minimum falls only a few times. */
#include <math.h>
#include <string.h>

#include "graphs/gamma_internal.h"

/* Distance from the centre within which every point that can change the summary lies. */
static double needed_radius(const gamma_summary *s, const gamma_frame *f, const double *coords)
{
    double need = f->r;
    for (int side = -1; side <= 1; side += 2) {
        uint32_t w = side > 0 ? s->up : s->lo;
        if (w == GAMMA_NONE) return INFINITY;
        double t = gamma_frame_offset(f, coords + (size_t)f->dim * w, side);
        if (!isfinite(t)) return INFINITY;
        need = fmax(need, fabs(t) + hypot(f->r, t));
    }
    return need * (1 + 1e-6);
}

/* Summary of one simplex by rings; 1 found, 0 none empty, -1 out of memory. */
static int simplex_params(const graph_grid *g, const uint32_t *simplex, fl_vec *ring, double *c0,
                          double *c1)
{
    gamma_frame f;
    *c0 = *c1 = NAN;
    if (!gamma_frame_init(&f, g->coords, g->dim, simplex)) return 0;
    gamma_summary s;
    gamma_summary_init(&s);
    for (size_t r = 0;; r++) {
        int beyond = 0;
        ring->count = 0;
        if (graph_grid_ring(g, f.center, r, ring, &beyond) < 0) return -1;
        if (beyond) break;
        const uint32_t *items = ring->data;
        for (size_t i = 0; i < ring->count; i++)
            gamma_summary_add(&s, &f, g->coords, items[i]);
        if (s.blocked_all) break; /* final: nothing can unblock it */
        if ((double)r * g->cell >= needed_radius(&s, &f, g->coords)) break;
    }
    gamma_value v;
    gamma_summary_value(&s, &f, g->coords, &v);
    if (v.never) return 0;
    *c0 = v.c0;
    *c1 = v.c1;
    return 1;
}

/* The points (finite, distinct) and every simplex (indices in range, no repeats). */
static fl_status check_input(const double *coords, size_t n, int dim, const uint32_t *simplices,
                             size_t count, fl_error *err)
{
    fl_status st = graph_check_points(coords, n, dim, err);
    if (st != FL_OK) return st;
    for (size_t i = 0; i < count; i++) {
        const uint32_t *s = simplices + (size_t)dim * i;
        for (int a = 0; a < dim; a++) {
            if (s[a] >= n)
                return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                               "simplex %zu: index %u out of range (%zu points)", i,
                               (unsigned)s[a], n);
            for (int b = 0; b < a; b++)
                if (s[a] == s[b])
                    return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                                   "simplex %zu repeats vertex %u", i, (unsigned)s[a]);
        }
    }
    return FL_OK;
}

/* Checks the input and, when there are simplices, builds the grid and an empty ring buffer
 * (the caller frees both); FL_OK with nothing built when count == 0. */
static fl_status batch_begin(const double *coords, size_t n, int dim, const uint32_t *simplices,
                             size_t count, graph_grid *g, fl_vec *ring, fl_error *err)
{
    fl_status st = check_input(coords, n, dim, simplices, count, err);
    if (st != FL_OK || count == 0) return st;
    st = graph_grid_build(g, coords, n, dim, err);
    if (st != FL_OK) return st;
    fl_vec_init(ring, sizeof(uint32_t));
    return FL_OK;
}

fl_status fl_gamma_simplices_params(const double *coords, size_t n, int dim,
                                    const uint32_t *simplices, size_t count, double *c0,
                                    double *c1, int *found, fl_error *err)
{
    if (count && (!simplices || !c0 || !c1))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "fl_gamma_simplices_params: simplices, c0 and c1 must not be NULL");
    graph_grid g;
    fl_vec ring;
    fl_status st = batch_begin(coords, n, dim, simplices, count, &g, &ring, err);
    if (st != FL_OK || count == 0) return st;
    for (size_t i = 0; i < count && st == FL_OK; i++) {
        int r = simplex_params(&g, simplices + (size_t)dim * i, &ring, c0 + i, c1 + i);
        if (r < 0)
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1,
                         "out of memory evaluating γ-neighbourhoods");
        else if (found)
            found[i] = r;
    }
    fl_vec_free(&ring);
    graph_grid_free(&g);
    return st;
}

/* The magnitude of the coordinates around a simplex (its centre, the grid's extent): the scale
 * of the rounding in the lens and ball tests below. */
static double coord_magnitude(const graph_grid *g, const gamma_frame *f)
{
    double mag = 0;
    for (int k = 0; k < g->dim; k++)
        mag = fmax(mag, fabs(f->center[k]) + fabs(g->lo[k]) + (double)g->res[k] * g->cell);
    return mag;
}

static int is_vertex(const uint32_t *simplex, int dim, uint32_t q)
{
    int own = 0;
    for (int k = 0; k < dim; k++) own |= simplex[k] == q;
    return own;
}

/* 1 when no point but the simplex's vertices lies in a lens slightly THICKER than N_γ(-kappa,
 * -kappa) (T shrunk by 1e-6, r^2 grown by 1e-9, |h| shrunk by an absolute 1e-12 of the
 * coordinates' magnitude for the rounding of h: rounding cannot hide a point), so that
 * c1' > -kappa for certain; 0 when some point may lie in it; -1 on NOMEM. As kappa -> 1 the lens
 * flattens to the disc of H within the smallest ball (T = inf): still decided, only points with
 * |h| within the rounding margin count. (It used to give up beyond T = 1e6 r; the minimum of
 * 3D constriction's flipped triangles reaches c1' = -1 + 1e-13 and every later triangle then
 * had an O(N) scan: over 10 minutes for 3e6 points.) */
static int lens_empty(const graph_grid *g, const gamma_frame *f, const uint32_t *simplex,
                      double kappa, fl_vec *box)
{
    double gk = 1 / (1 - kappa), t = f->r * sqrt(gk * gk - 1) * (1 - 1e-6);
    if (!(kappa > 0 && kappa < 1) || !(t >= 0) || !(f->r > 0)) return 0;
    int dim = g->dim;
    double lo[3], hi[3], reach = f->r * (1 + 1e-6);
    for (int k = 0; k < dim; k++) lo[k] = f->center[k] - reach, hi[k] = f->center[k] + reach;
    double mag = coord_magnitude(g, f); /* the rounding scale */
    double herr = 1e-12 * (reach + mag);
    /* d2 >= 0, so a point in the lens has |h| < r^2 / (2T): only cells meeting that slab (with
     * the margin for the rounding of h) can hold one */
    double half = f->r * f->r * (1 + 1e-9) / (2 * t) * (1 + 1e-6) + herr;
    if (!isfinite(half) || !isfinite(herr)) return 0;
    box->count = 0;
    if (graph_grid_slab(g, lo, hi, f->center, f->normal, half, box) < 0) return -1;
    const uint32_t *items = box->data;
    double r2 = f->r * f->r * (1 + 1e-9);
    for (size_t i = 0; i < box->count; i++) {
        uint32_t q = items[i];
        if (is_vertex(simplex, dim, q)) continue;
        const double *p = g->coords + (size_t)dim * q;
        double d2 = 0, h = 0;
        for (int k = 0; k < dim; k++) {
            double d = p[k] - f->center[k];
            d2 += d * d;
            h += d * f->normal[k];
        }
        double hh = fmax(fabs(h) - herr, 0); /* t * 0 would be NaN for t = inf */
        if (d2 < r2 && (hh == 0 || 2 * t * hh < r2 - d2)) return 0;
    }
    return 1;
}

/* 1 when, for m in [0, 1), one of the two balls B(+t_m), B(-t_m) touching the simplex's
 * vertices with magnitude m (radius R = r / (1 - m), offset t_m = sqrt(R^2 - r^2), the
 * magnitude of ball_magnitude in gamma_simplex.c) is certainly empty: no point but the
 * vertices lies within R (1 + 1e-6) + 1e-12 mag of its centre. Then the simplex has an empty
 * ball, so it is Delaunay, and the empty offsets [tau(lo), tau(up)] reach past t_m (or -t_m):
 * c1' = the larger magnitude of their ends >= m. The margin makes the certified ball slightly
 * larger than B(t_m), so c1' exceeds m by more than the rounding of its own computation.
 * 0 when both may hold a point, -1 on NOMEM. */
static int side_ball_empty(const graph_grid *g, const gamma_frame *f, const uint32_t *simplex,
                           double m, fl_vec *box)
{
    if (!(m >= 0 && m < 1) || !(f->r > 0)) return 0;
    int dim = g->dim;
    double big = f->r / (1 - m), t = sqrt(fmax(big * big - f->r * f->r, 0));
    double mag = coord_magnitude(g, f); /* the rounding scale */
    double reach = big * (1 + 1e-6) + 1e-12 * (mag + big + t);
    if (!isfinite(reach)) return 0;
    for (int side = -1; side <= 1; side += 2) {
        double c[3], lo[3], hi[3];
        for (int k = 0; k < dim; k++) {
            c[k] = f->center[k] + side * t * f->normal[k];
            lo[k] = c[k] - reach, hi[k] = c[k] + reach;
        }
        box->count = 0;
        if (graph_grid_slab(g, lo, hi, c, f->normal, reach, box) < 0) return -1;
        const uint32_t *items = box->data;
        int empty = 1;
        for (size_t i = 0; i < box->count && empty; i++) {
            uint32_t q = items[i];
            if (is_vertex(simplex, dim, q)) continue;
            const double *p = g->coords + (size_t)dim * q;
            double d2 = 0;
            for (int k = 0; k < dim; k++) d2 += (p[k] - c[k]) * (p[k] - c[k]);
            empty = !(d2 < reach * reach);
        }
        if (empty) return 1;
    }
    return 0;
}

fl_status fl_gamma_simplices_min_c1(const double *coords, size_t n, int dim,
                                    const uint32_t *simplices, size_t count, double *min_c1,
                                    size_t *argmin, fl_error *err)
{
    if (!min_c1 || (count && !simplices))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "fl_gamma_simplices_min_c1: simplices and min_c1 must not be NULL");
    *min_c1 = NAN;
    if (argmin) *argmin = count;
    double c0 = NAN, c1 = NAN;
    graph_grid g;
    fl_vec ring;
    fl_status st = batch_begin(coords, n, dim, simplices, count, &g, &ring, err);
    if (st != FL_OK || count == 0) return st;
    double m = NAN;
    size_t at = count;
    for (size_t i = 0; i < count && st == FL_OK && !(m <= -1); i++) {
        const uint32_t *s = simplices + (size_t)dim * i;
        gamma_frame f;
        int r = 0;
        if (gamma_frame_init(&f, g.coords, dim, s) && !isnan(m)) {
            r = m < 0 ? lens_empty(&g, &f, s, -m, &ring) : side_ball_empty(&g, &f, s, m, &ring);
            if (r > 0) continue; /* c1' > m (or >= m, after an earlier index): not the minimum */
        }
        if (r < 0 || (r = simplex_params(&g, s, &ring, &c0, &c1)) < 0) {
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory evaluating γ-neighbourhoods");
            break;
        }
        if (r == 0) c1 = -1; /* no empty neighbourhood: the end of the range */
        if (isnan(m) || c1 < m) m = c1, at = i;
    }
    fl_vec_free(&ring);
    graph_grid_free(&g);
    if (st == FL_OK) {
        *min_c1 = m;
        if (argmin) *argmin = at;
    }
    return st;
}

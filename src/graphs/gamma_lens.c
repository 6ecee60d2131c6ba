/* Output-sensitive construction of the non-Delaunay edges of a 2D γ-graph (c1' < 0).
 *
 * The thesis leaves this open (§3.6: "the most urgent is the development of output-sensitive
 * algorithms"); Theorem 3.1's brute force costs O(N^3) in 2D. Two facts make it local:
 *
 * 1. An edge with c1' >= -kappa has an empty symmetric lens N_γ(-kappa,-kappa) (Lemma 3.2 with
 *    c0 = c1 = -kappa, since |c0'| <= |c1'| <= kappa). That lens is the intersection of two discs
 *    of radius rho = r/(1-kappa) through v, w and contains the rhombus v, m+s*n, w, m-s*n
 *    (m the midpoint, s = r*phi, phi = 1/(1-kappa) - sqrt(1/(1-kappa)^2 - 1)), hence the cone at v
 *    of half-angle theta = atan(phi) cut at distance r = |vw|/2. Split the directions around v
 *    into sectors narrower than theta: if some point p of w's sector lies closer to v than |vw|/2,
 *    p is inside that cone and blocks vw. So only the points of a sector within twice the
 *    sector's nearest distance are candidates, at both ends of the edge (a Yao-graph filter).
 * 2. A candidate's witnesses (gamma_simplex.c) lie on balls B(t) with |t| <= T = sqrt(rho^2-r^2)
 *    when c1' >= -kappa, and every point that could beat a witness lies inside its ball. So the
 *    summary is gathered from the grid cells around the smallest ball and then around the
 *    witnesses' balls (capped at B(+-T)); it is the global one whenever it reports a
 *    non-Delaunay edge with c1' >= -kappa, and otherwise the edge is Delaunay (built elsewhere)
 *    or has c1' < -kappa (rejected either way). See verify_edge.
 *
 * On uniform points each vertex keeps O(1) candidates a sector, so the work is
 * O(N * K * points-per-lens) with K = O(1/theta) sectors; no O(N^3) step remains. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "graphs/gamma_internal.h"

#define GAMMA_PI 3.14159265358979323846
#define LENS_SLACK 1e-9 /* relative margin so floating filters never drop a true candidate */

typedef struct lens_ctx {
    const double *xy;
    size_t n;
    graph_grid grid;
    size_t sectors;
    double width; /* angular width of a sector */
    double bbox[4];
    double *dmin; /* n * sectors nearest distances (INFINITY: none) */
} lens_ctx;

static size_t sector_of(const lens_ctx *c, double dx, double dy)
{
    double a = atan2(dy, dx) + GAMMA_PI;
    size_t s = (size_t)(a / c->width);
    return s >= c->sectors ? c->sectors - 1 : s;
}

/* Distance from p along direction angle `a` to the boundary of the bounding box. */
static double ray_exit(const lens_ctx *c, const double *p, double a)
{
    double d[2] = {cos(a), sin(a)}, t = INFINITY;
    for (int k = 0; k < 2; k++) {
        if (d[k] > 0) t = fmin(t, (c->bbox[2 + k] - p[k]) / d[k]);
        if (d[k] < 0) t = fmin(t, (c->bbox[k] - p[k]) / d[k]);
    }
    return isinf(t) ? 0 : fmax(t, 0);
}

/* How far sector s of p reaches inside the bounding box: its two rays and the corners in it. */
static double sector_reach(const lens_ctx *c, const double *p, size_t s)
{
    double a0 = -GAMMA_PI + (double)s * c->width;
    double reach = fmax(ray_exit(c, p, a0), ray_exit(c, p, a0 + c->width));
    for (int k = 0; k < 4; k++) {
        double q[2] = {c->bbox[(k & 1) ? 2 : 0], c->bbox[(k & 2) ? 3 : 1]};
        double dx = q[0] - p[0], dy = q[1] - p[1];
        if ((dx != 0 || dy != 0) && sector_of(c, dx, dy) == s) reach = fmax(reach, hypot(dx, dy));
    }
    return reach;
}

/* Scans rings of cells around v until every sector's candidates (within twice its nearest
 * distance) are seen; fills dmin for v and leaves the scanned points in `seen`. */
static int scan_vertex(lens_ctx *c, uint32_t v, fl_vec *seen)
{
    const double *p = c->xy + 2 * (size_t)v;
    double *dmin = c->dmin + (size_t)v * c->sectors;
    for (size_t s = 0; s < c->sectors; s++)
        dmin[s] = INFINITY;
    seen->count = 0;
    for (size_t ring = 0;; ring++) {
        size_t first = seen->count;
        int beyond = 0;
        if (graph_grid_ring(&c->grid, p, ring, seen, &beyond) < 0) return -1;
        for (size_t i = first; i < seen->count; i++) {
            uint32_t w = ((uint32_t *)seen->data)[i];
            if (w == v) continue;
            double dx = c->xy[2 * (size_t)w] - p[0], dy = c->xy[2 * (size_t)w + 1] - p[1];
            size_t s = sector_of(c, dx, dy);
            dmin[s] = fmin(dmin[s], hypot(dx, dy));
        }
        if (beyond) return 0;
        double need = 0;
        for (size_t s = 0; s < c->sectors; s++)
            need = fmax(need, isinf(dmin[s]) ? sector_reach(c, p, s) : 2 * dmin[s]);
        if ((double)ring * c->grid.cell > need * (1 + LENS_SLACK)) return 0;
    }
}

/* Does w pass the sector filter seen from v? */
static int passes_filter(const lens_ctx *c, uint32_t v, uint32_t w)
{
    double dx = c->xy[2 * (size_t)w] - c->xy[2 * (size_t)v];
    double dy = c->xy[2 * (size_t)w + 1] - c->xy[2 * (size_t)v + 1];
    double d = hypot(dx, dy), m = c->dmin[(size_t)v * c->sectors + sector_of(c, dx, dy)];
    return d <= 2 * m * (1 + LENS_SLACK);
}

/* Adds to the summary every point of the grid cells meeting the bounding box of the ball B(t)
 * (t = 0: the smallest ball). Repeats are harmless: a point never beats itself. */
static int add_ball(lens_ctx *c, const gamma_frame *f, double t, fl_vec *local, gamma_summary *s)
{
    double radius = hypot(f->r, t) * (1 + LENS_SLACK), lo[2], hi[2];
    for (int k = 0; k < 2; k++) {
        double centre = f->center[k] + t * f->normal[k];
        double slack = LENS_SLACK * (fabs(centre) + radius);
        lo[k] = centre - radius - slack;
        hi[k] = centre + radius + slack;
    }
    local->count = 0;
    if (graph_grid_box(&c->grid, lo, hi, local)) return -1;
    for (size_t i = 0; i < local->count; i++)
        gamma_summary_add(s, f, c->xy, ((uint32_t *)local->data)[i]);
    return 0;
}

/* The centre offset tau of a witness's ball, in the frame's floating construction. */
static double witness_tau(const lens_ctx *c, const gamma_frame *f, uint32_t w)
{
    const double *p = c->xy + 2 * (size_t)w;
    double d[2] = {p[0] - f->center[0], p[1] - f->center[1]};
    double h = d[0] * f->normal[0] + d[1] * f->normal[1];
    return (d[0] * d[0] + d[1] * d[1] - f->r * f->r) / (2 * h);
}

/* The summary of edge e is gathered in two rounds. Round one: the smallest ball (which holds
 * every point on the open edge) and, for a side without a point there, the extreme ball B(+-T)
 * of an edge with c1' >= -kappa. Round two: the balls of the witnesses found, capped at B(+-T).
 * A point beating a round-two witness lies in that witness's ball (on its side the balls are
 * nested in t), so the final witnesses are the global ones whenever their balls stay within
 * B(+-T), which is exactly when the edge can have c1' >= -kappa. */
static int verify_edge(lens_ctx *c, const fl_gamma_params *p, double kappa, const uint32_t *e,
                       fl_vec *local, graph_builder *b)
{
    gamma_frame f;
    if (!gamma_frame_init(&f, c->xy, 2, e)) return 0;
    double g = 1 / (1 - kappa), t_max = f.r * sqrt(g * g - 1);
    gamma_summary s;
    gamma_summary_init(&s);
    if (add_ball(c, &f, 0, local, &s)) return -1;
    if (s.blocked_all) return 0;
    if (s.up == GAMMA_NONE && add_ball(c, &f, t_max, local, &s)) return -1;
    if (s.lo == GAMMA_NONE && add_ball(c, &f, -t_max, local, &s)) return -1;
    if (s.up == GAMMA_NONE || s.lo == GAMMA_NONE) return 0; /* Delaunay or c1' < -kappa */
    gamma_value val;
    gamma_summary_value(&s, &f, c->xy, &val);
    /* More points only widen the interval [tau(up), tau(lo)] of a non-Delaunay edge, so its
     * |c1'| can only grow: an early c1' < -kappa is final. */
    if (!val.delaunay && val.c1 < -kappa) return 0;
    double tu = fmin(witness_tau(c, &f, s.up), t_max), tl = fmax(witness_tau(c, &f, s.lo), -t_max);
    if (add_ball(c, &f, tu, local, &s) || add_ball(c, &f, tl, local, &s)) return -1;
    gamma_summary_value(&s, &f, c->xy, &val);
    if (val.never || val.delaunay || val.c1 < -kappa || !gamma_params_accept(p, &val)) return 0;
    return graph_builder_add(b, e, val.c0, val.c1);
}

static fl_status collect_candidates(lens_ctx *c, fl_vec *pairs, fl_vec *seen,
                                    const fl_graph_options *opt, fl_error *err)
{
    fl_progress_fn progress = opt ? opt->progress : NULL;
    void *user = opt ? opt->progress_user : NULL;
    for (uint32_t v = 0; v < c->n; v++) {
        if ((v & 1023) == 0 &&
            fl_progress(progress, user, "gamma lens candidates", 0.5 * v / (double)c->n))
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
        if (scan_vertex(c, v, seen)) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
        for (size_t i = 0; i < seen->count; i++) {
            uint32_t e[2] = {v, ((uint32_t *)seen->data)[i]};
            if (e[1] > v && passes_filter(c, v, e[1]) && fl_vec_push(pairs, e, 1))
                return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
        }
    }
    return FL_OK;
}

static fl_status verify_candidates(lens_ctx *c, const fl_gamma_params *p, double kappa,
                                   const fl_vec *pairs, const fl_graph_options *opt,
                                   graph_builder *b, fl_error *err)
{
    fl_progress_fn progress = opt ? opt->progress : NULL;
    void *user = opt ? opt->progress_user : NULL;
    fl_vec local;
    fl_vec_init(&local, sizeof(uint32_t));
    const uint32_t *e = pairs->data;
    fl_status st = FL_OK;
    for (size_t i = 0; i < pairs->count && st == FL_OK; i++) {
        if ((i & 4095) == 0 && fl_progress(progress, user, "gamma lens verification",
                                           0.5 + 0.5 * i / (double)pairs->count))
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
        else if (passes_filter(c, e[2 * i + 1], e[2 * i]) &&
                 verify_edge(c, p, kappa, e + 2 * i, &local, b) < 0)
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    fl_vec_free(&local);
    return st;
}

fl_status gamma_lens_edges(const double *xy, size_t n, const fl_gamma_params *p, double kappa,
                           const fl_graph_options *opt, graph_builder *b, fl_error *err)
{
    lens_ctx c;
    memset(&c, 0, sizeof c);
    c.xy = xy;
    c.n = n;
    double g = 1 / (1 - kappa);
    double phi = 1 / (g + sqrt(g * g - 1)); /* g - sqrt(g^2-1) without cancellation */
    c.sectors = (size_t)ceil(2 * GAMMA_PI / atan(phi) * 1.02) + 1;
    c.width = 2 * GAMMA_PI / (double)c.sectors;
    c.bbox[0] = c.bbox[2] = n ? xy[0] : 0;
    c.bbox[1] = c.bbox[3] = n ? xy[1] : 0;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 2; k++) {
            c.bbox[k] = fmin(c.bbox[k], xy[2 * i + k]);
            c.bbox[2 + k] = fmax(c.bbox[2 + k], xy[2 * i + k]);
        }
    fl_status st = graph_grid_build(&c.grid, xy, n, 2, err);
    if (st != FL_OK) return st;
    c.dmin = fl_alloc_array(n, c.sectors * sizeof(double));
    fl_vec pairs, seen;
    fl_vec_init(&pairs, 2 * sizeof(uint32_t));
    fl_vec_init(&seen, sizeof(uint32_t));
    if (!c.dmin)
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu sectors", c.sectors);
    if (st == FL_OK) st = collect_candidates(&c, &pairs, &seen, opt, err);
    if (st == FL_OK) st = verify_candidates(&c, p, kappa, &pairs, opt, b, err);
    fl_vec_free(&pairs);
    fl_vec_free(&seen);
    free(c.dmin);
    graph_grid_free(&c.grid);
    return st;
}

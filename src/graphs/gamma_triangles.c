/* The exact decision for the non-Delaunay triangles (c1' < 0) of a 3D γ-graph: each candidate
 * triangle of gamma3_edges.c (generated around its shortest edge) is decided by a scan of the
 * points stopped as soon as the triangle is decided (see docs/gamma.md, "Construction").
 *
 * Theorem 3.1 tests every triangle against every point. The parameters accept only
 * triangles with c1' >= -kappa, whose largest empty neighbourhood contains the symmetric lens
 * N_γ(-kappa,-kappa) = B(-T) ∩ B(T) (Lemma 3.2; T = r*sqrt(g^2-1), g = 1/(1-kappa), as in
 * gamma_lens.c). The points are visited in rings of grid cells around the circumcentre, nearest
 * first, and the scan stops
 *  - as soon as a witness lies inside that lens (its |c| exceeds kappa on the far side), or a
 *    point lies in the open triangle, or the partial summary already gives c1' < -kappa: more
 *    points only widen the witness interval [tau(up), tau(lo)] of a non-Delaunay triangle
 *    (gamma_simplex.c), so such a rejection is final;
 *  - once every point that could still beat a witness has been seen (needed_radius).
 * The lens contains the ball of radius r*phi around the circumcentre, so almost every rejected
 * triangle is rejected by the first points of its first rings. An accepted triangle's witnesses
 * are the global ones, so its summary, and hence c0', c1', are the brute force's bit for bit;
 * floating comparisons with kappa keep a margin that sends borderline values to the full scan. */
#include <math.h>
#include <string.h>

#include "graphs/gamma_internal.h"

/* Does the witness w (on side `side`) alone reject the triangle? Its ball B(tau) on w's side
 * of H reaches beyond B(-+T), the boundary of the symmetric lens N_γ(-kappa,-kappa), when tau
 * lies on the far side with |c| > kappa: then c1' <= -|c| < -kappa if no ball is empty, and a
 * triangle with an empty ball is Delaunay, not wanted here either (gamma_simplex.c). The
 * magnitude is the one gamma_summary_value uses; the margin leaves values within rounding of
 * kappa to the full scan. */
static int witness_rejects(const gamma_frame *f, const double *coords, uint32_t w, int side,
                           double kappa)
{
    double t = gamma_frame_offset(f, coords + 3 * (size_t)w, side);
    if (t * side >= 0) return 0;
    double q = fabs(t) / f->r, m = isinf(q) ? 1.0 : 1 - 1 / hypot(1.0, q);
    return m > kappa * (1 + 1e-9) + 1e-300;
}

/* Is the partial summary already final as a rejection? */
static int rejected_early(const gamma_summary *s, const gamma_frame *f, const double *coords,
                          double kappa)
{
    if (s->blocked_all) return 1;
    if (s->up == GAMMA_NONE || s->lo == GAMMA_NONE) return 0;
    gamma_value v;
    gamma_summary_value(s, f, coords, &v);
    /* A margin so that a value within rounding of -kappa is always scanned to the end. */
    return !v.delaunay && v.c1 < -kappa * (1 + 1e-9) - 1e-300;
}

/* The distance from the circumcentre within which every point that can still change the
 * decision lies. A point beating the witness on the + side is inside B(tau(up)) on that side;
 * an accepted triangle has |tau| <= T (its lens contains N_γ(-kappa,-kappa) = B(-T) ∩ B(T),
 * gamma_lens.c), so the offsets are capped at T' = T(1 + 1e-6): an unseen point then has
 * |c| > kappa and cannot make a rejected triangle acceptable, nor change an accepted one's
 * witnesses (gamma_lens.c's verify_edge makes the same argument in 2D). Points on H that matter
 * are inside the circumcircle. B(t) lies within |t| + sqrt(r^2 + t^2) of the centre. */
static double needed_radius(const gamma_summary *s, const gamma_frame *f, const double *coords,
                            double t_cap)
{
    double need = f->r;
    for (int side = -1; side <= 1; side += 2) {
        uint32_t w = side > 0 ? s->up : s->lo;
        double t = t_cap;
        if (w != GAMMA_NONE) {
            t = gamma_frame_offset(f, coords + 3 * (size_t)w, side);
            t = fmin(fmax(t, -t_cap), t_cap);
        }
        need = fmax(need, fabs(t) + hypot(f->r, t));
    }
    return need * (1 + 1e-6);
}

/* Scans the points ring by ring around the circumcentre; returns 1 when rejected early, 0 when
 * every point that matters was added, -1 out of memory. */
static int scan_triangle(const graph_grid *g, const gamma_frame *f, double kappa, fl_vec *ring,
                         gamma_summary *s)
{
    double gk = 1 / (1 - kappa), t_cap = f->r * sqrt(gk * gk - 1) * (1 + 1e-6);
    for (size_t r = 0;; r++) {
        int beyond = 0;
        ring->count = 0;
        if (graph_grid_ring(g, f->center, r, ring, &beyond) < 0) return -1;
        if (beyond) return 0;
        const uint32_t *items = ring->data;
        for (size_t i = 0; i < ring->count; i++) {
            uint32_t up = s->up, lo = s->lo;
            gamma_summary_add(s, f, g->coords, items[i]);
            if (s->blocked_all) return 1;
            if (s->up != up && witness_rejects(f, g->coords, s->up, +1, kappa)) return 1;
            if (s->lo != lo && witness_rejects(f, g->coords, s->lo, -1, kappa)) return 1;
        }
        if (rejected_early(s, f, g->coords, kappa)) return 1;
        if ((double)r * g->cell >= needed_radius(s, f, g->coords, t_cap)) return 0;
    }
}

int gamma_triangle_check(const graph_grid *g, const fl_gamma_params *p, double kappa,
                         const uint32_t *t, fl_vec *ring, graph_builder *b)
{
    gamma_frame f;
    if (!gamma_frame_init(&f, g->coords, 3, t)) return 0;
    gamma_summary s;
    gamma_summary_init(&s);
    int r = scan_triangle(g, &f, kappa, ring, &s);
    if (r != 0) return r < 0 ? -1 : 0;
    gamma_value v;
    gamma_summary_value(&s, &f, g->coords, &v);
    if (v.never || v.delaunay || !gamma_params_accept(p, &v)) return 0;
    return graph_builder_add(b, t, v.c0, v.c1);
}

fl_status gamma_lens_triangles(const double *xyz, size_t n, const fl_gamma_params *p, double kappa,
                               const fl_graph_options *opt, graph_builder *b, fl_error *err)
{
    graph_grid g;
    fl_status st = graph_grid_build(&g, xyz, n, 3, err);
    if (st != FL_OK) return st;
    st = gamma3_edge_triangles(&g, p, kappa, opt, b, err);
    graph_grid_free(&g);
    return st;
}

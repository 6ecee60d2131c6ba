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

#include "graphs/gamma3_search.h"

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

/* Adds point i to the summary; returns 1 when that rejects the triangle for good. */
static int add_point(gamma_summary *s, const gamma_frame *f, const double *coords, uint32_t i,
                     double kappa)
{
    uint32_t up = s->up, lo = s->lo;
    gamma_summary_add(s, f, coords, i);
    if (s->blocked_all) return 1;
    if (s->up != up && witness_rejects(f, coords, s->up, +1, kappa)) return 1;
    if (s->lo != lo && witness_rejects(f, coords, s->lo, -1, kappa)) return 1;
    return 0;
}

/* The cap T' = T (1 + 1e-6) of the witness offsets (needed_radius). */
static double offset_cap(const gamma_frame *f, double kappa)
{
    double gk = 1 / (1 - kappa);
    return f->r * sqrt(gk * gk - 1) * (1 + 1e-6);
}

/* Scans the points ring by ring around the circumcentre; returns 1 when rejected early, 0 when
 * every point that matters was added, -1 out of memory. */
static int scan_triangle(const graph_grid *g, const gamma_frame *f, double kappa, fl_vec *ring,
                         gamma_summary *s)
{
    double t_cap = offset_cap(f, kappa);
    for (size_t r = 0;; r++) {
        int beyond = 0;
        ring->count = 0;
        if (graph_grid_ring(g, f->center, r, ring, &beyond) < 0) return -1;
        if (beyond) return 0;
        const uint32_t *items = ring->data;
        for (size_t i = 0; i < ring->count; i++)
            if (add_point(s, f, g->coords, items[i], kappa)) return 1;
        if (rejected_early(s, f, g->coords, kappa)) return 1;
        if ((double)r * g->cell >= needed_radius(s, f, g->coords, t_cap)) return 0;
    }
}

/* The region a side's points must be searched in (the kd walk of scan_triangle_kd): the ball
 * B(t) of centre C + t n, radius sqrt(r^2 + t^2), t the offset of the side's witness clamped
 * to [-T', T'] (T' with no witness yet: +T' above H, -T' below), and only its part on that
 * side of H. A point p of side +1 lies in the closed B(t) iff tau(p) <= t, of side -1 iff
 * tau(p) >= t, so the part of B(t) on the side shrinks as the witness improves (tau(up) only
 * decreases, tau(lo) only increases). */
typedef struct side_ball {
    double z[3], rad, slack;
} side_ball;

static void side_ball_set(side_ball *b, const gamma_summary *s, const gamma_frame *f,
                          const double *coords, double t_cap, int side)
{
    uint32_t w = side > 0 ? s->up : s->lo;
    double t = side * t_cap;
    if (w != GAMMA_NONE)
        t = fmin(fmax(gamma_frame_offset(f, coords + 3 * (size_t)w, side), -t_cap), t_cap);
    for (int k = 0; k < 3; k++)
        b->z[k] = f->center[k] + t * f->normal[k];
    b->rad = hypot(f->r, t);
    /* The relative margin of needed_radius, on the distance from C this ball reaches. */
    b->slack = 1e-6 * (fabs(t) + b->rad);
}

/* May the box hold a point of side `side` in the closed ball b (up to its slack)? */
static int box_meets(const gamma3_kd_node *nd, const gamma_frame *f, const side_ball *b, int side)
{
    double d2 = 0, reach = 0;
    for (int k = 0; k < 3; k++) {
        double below = nd->lo[k] - b->z[k], above = b->z[k] - nd->hi[k];
        double gap = below > 0 ? below : above > 0 ? above : 0;
        d2 += gap * gap;
        double mid = 0.5 * (nd->lo[k] + nd->hi[k]), half = 0.5 * (nd->hi[k] - nd->lo[k]);
        reach += side * f->normal[k] * (mid - f->center[k]) + half * fabs(f->normal[k]);
    }
    double rad = b->rad + b->slack;
    return d2 <= rad * rad && reach >= -b->slack;
}

/* scan_triangle over a kd-tree of the points: the boxes are walked nearest child first and a
 * box is skipped when it can hold no point of side +1 in the current B(t_up) nor one of side
 * -1 in B(t_lo) (side_ball; points on H inside the closed circumcircle lie in both balls and on
 * both sides' closed half-spaces, so they are never skipped). Since those regions only shrink,
 * a skipped point stays outside them: it has tau beyond its side's clamped witness offset, so
 * it cannot beat a witness with |tau| <= T', and when the witness is beyond T' (or missing) the
 * triangle is rejected whatever such points add, as in needed_radius. Early rejections are final
 * for any set of points. So, like the rings, this reaches the brute force's decision and, for an
 * accepted triangle, its witnesses; it sees far fewer points, since the balls lie inside
 * needed_radius's ball around C and only their parts on their own side matter. */
static int scan_triangle_kd(const gamma3_kdtree *kd, const gamma_frame *f, double kappa,
                            fl_vec *stack, gamma_summary *s)
{
    const double *coords = kd->xyz;
    double t_cap = offset_cap(f, kappa);
    side_ball up, lo;
    side_ball_set(&up, s, f, coords, t_cap, +1);
    side_ball_set(&lo, s, f, coords, t_cap, -1);
    stack->count = 0;
    uint32_t root = 0;
    if (fl_vec_push(stack, &root, 1)) return -1;
    while (stack->count) {
        const gamma3_kd_node *nd = &kd->nodes[((uint32_t *)stack->data)[--stack->count]];
        if (!box_meets(nd, f, &up, +1) && !box_meets(nd, f, &lo, -1)) continue;
        if (nd->child) {
            uint32_t ch[2] = {nd->child, nd->child + 1};
            double dc[2];
            for (int j = 0; j < 2; j++) {
                const gamma3_kd_node *x = &kd->nodes[ch[j]];
                dc[j] = 0;
                for (int k = 0; k < 3; k++) {
                    double v = 0.5 * (x->lo[k] + x->hi[k]) - f->center[k];
                    dc[j] += v * v;
                }
            }
            uint32_t order[2] = {dc[0] > dc[1] ? ch[0] : ch[1], dc[0] > dc[1] ? ch[1] : ch[0]};
            if (fl_vec_push(stack, order, 2)) return -1;
            continue;
        }
        uint32_t was_up = s->up, was_lo = s->lo;
        for (uint32_t i = nd->begin; i < nd->end; i++)
            if (add_point(s, f, coords, kd->perm[i], kappa)) return 1;
        if (s->up != was_up || s->lo != was_lo) {
            if (rejected_early(s, f, coords, kappa)) return 1;
            if (s->up != was_up) side_ball_set(&up, s, f, coords, t_cap, +1);
            if (s->lo != was_lo) side_ball_set(&lo, s, f, coords, t_cap, -1);
        }
    }
    return 0;
}

/* The decision for t: the scan over the kd-tree when kd is given, else the grid's rings; adds
 * t when the summary says it is non-Delaunay and accepted. */
static int check(const graph_grid *g, const gamma3_kdtree *kd, const fl_gamma_params *p,
                 double kappa, const uint32_t *t, fl_vec *scratch, graph_builder *b)
{
    const double *coords = kd ? kd->xyz : g->coords;
    gamma_frame f;
    if (!gamma_frame_init(&f, coords, 3, t)) return 0;
    gamma_summary s;
    gamma_summary_init(&s);
    int r = kd ? scan_triangle_kd(kd, &f, kappa, scratch, &s)
               : scan_triangle(g, &f, kappa, scratch, &s);
    if (r != 0) return r < 0 ? -1 : 0;
    gamma_value v;
    gamma_summary_value(&s, &f, coords, &v);
    if (v.never || v.delaunay || !gamma_params_accept(p, &v)) return 0;
    return graph_builder_add(b, t, v.c0, v.c1);
}

int gamma_triangle_check(const graph_grid *g, const fl_gamma_params *p, double kappa,
                         const uint32_t *t, fl_vec *ring, graph_builder *b)
{
    return check(g, NULL, p, kappa, t, ring, b);
}

int gamma_triangle_check_kd(const gamma3_kdtree *kd, const fl_gamma_params *p, double kappa,
                            const uint32_t *t, fl_vec *stack, graph_builder *b)
{
    return check(NULL, kd, p, kappa, t, stack, b);
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

/* The 3D flintstone of an open polyhedron (thesis §7.3.1, Def. 7.5; widths Def. 7.6).
 *
 * For a node with corners v_p, v_s, v_t the balls through the corners form a pencil; on each
 * side of the corners' plane the balls of the pencil are nested there, so the ball through the
 * corners and the vertex v_q that contains every vertex of the part on v_q's side is found by
 * one scan that replaces the candidate whenever a vertex lies outside its ball (fl_insphere,
 * exact). v_r is the same on the other side. The ± operator (Def. 7.2) on the signed radii
 * decides intersection or union. The balls are then stored in floating point with a squared
 * radius equal to the largest computed squared distance to a vertex they must hold (enlarged by
 * FL_HAL3_REL when tested), so containment is proven by construction, not by trusting the
 * floating centre:
 *  - intersection: each ball holds every vertex; the intersection of two balls is convex, so it
 *    holds every triangle of the part;
 *  - union: ball[0] holds the vertices on v_q's side, ball[1] those on v_r's; a union is not
 *    convex, so it is kept only when every triangle has its three vertices in one ball;
 *    otherwise (a triangle crossing the plane outside the corners' circle, the degenerate case
 *    the thesis mentions) the node falls back to the intersection of the two balls enlarged
 *    to hold every vertex;
 *  - half-space: every vertex is on one side; the exact fl_orient3d decides the half-space.
 * The node error is the largest distance of a vertex of the part to the node's triangle: the
 * distance to a triangle is convex, so over each original triangle it is largest at a vertex,
 * and this bounds the distance of every point of the part (the one-sided Hausdorff distance). */
#include <math.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal3_internal.h"
#include "mesh/intersect.h"

static const double *vx(const fl_mesh *m, uint32_t v)
{
    return m->xyz + 3 * (size_t)v;
}

static void sub(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0], r[1] = a[1] - b[1], r[2] = a[2] - b[2];
}

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

/* Centre of the sphere through p, s, t, q (floating construction). */
static void circumcentre(const double *p, const double *s, const double *t, const double *q,
                         double *c)
{
    double a[3], b[3], d[3], bxd[3], dxa[3], axb[3];
    sub(s, p, a), sub(t, p, b), sub(q, p, d);
    cross(b, d, bxd), cross(d, a, dxa), cross(a, b, axb);
    double den = 2 * dot(a, bxd);
    double la = dot(a, a), lb = dot(b, b), ld = dot(d, d);
    for (int k = 0; k < 3; k++)
        c[k] = p[k] + (la * bxd[k] + lb * dxa[k] + ld * axb[k]) / den;
}

/* Distance from x to the closed triangle abc (Ericson, Real-Time Collision Detection §5.1.5).
 * The region tests multiply dot products, i.e. 4th powers of the coordinates: at 1e100 they
 * overflowed (inf / inf = NaN), the distance came out NaN and fmax dropped it, so a node's
 * certified error was 0 with a vertex 1.75e100 away (found by fuzz/fuzz_hal3.c). The tests run
 * on the differences scaled by a power of two (exact, and the tests are scale invariant); the
 * closest point is built from the unscaled ones. */
static double point_triangle_distance(const double *x, const double *a, const double *b,
                                      const double *c)
{
    double ab[3], ac[3], ap[3], bp[3], cp[3], r[3];
    sub(b, a, ab), sub(c, a, ac), sub(x, a, ap), sub(x, b, bp), sub(x, c, cp);
    double mx = 0, f = 1, sab[3], sac[3], sap[3], sbp[3], scp[3];
    for (int k = 0; k < 3; k++)
        mx = fmax(mx, fmax(fmax(fabs(ab[k]), fabs(ac[k])),
                           fmax(fabs(ap[k]), fmax(fabs(bp[k]), fabs(cp[k])))));
    if (mx > 0 && isfinite(mx)) f = ldexp(1.0, -ilogb(mx));
    for (int k = 0; k < 3; k++)
        sab[k] = f * ab[k], sac[k] = f * ac[k], sap[k] = f * ap[k], sbp[k] = f * bp[k],
        scp[k] = f * cp[k];
    double d1 = dot(sab, sap), d2 = dot(sac, sap);
    const double *q = NULL;
    double v = 0, w = 0;
    if (d1 <= 0 && d2 <= 0) q = a;
    double d3 = dot(sab, sbp), d4 = dot(sac, sbp);
    if (!q && d3 >= 0 && d4 <= d3) q = b;
    double d5 = dot(sab, scp), d6 = dot(sac, scp);
    if (!q && d6 >= 0 && d5 <= d6) q = c;
    if (q) {
        sub(x, q, r);
        return sqrt(dot(r, r));
    }
    double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    double pt[3];
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        v = d1 / (d1 - d3);
        for (int k = 0; k < 3; k++)
            pt[k] = a[k] + v * ab[k];
    } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        w = d2 / (d2 - d6);
        for (int k = 0; k < 3; k++)
            pt[k] = a[k] + w * ac[k];
    } else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (int k = 0; k < 3; k++)
            pt[k] = b[k] + w * (c[k] - b[k]);
    } else {
        double den = va + vb + vc;
        if (!(fabs(den) > 0)) return sqrt(dot(ap, ap)); /* degenerate: fall back to a corner */
        v = vb / den, w = vc / den;
        for (int k = 0; k < 3; k++)
            pt[k] = a[k] + ab[k] * v + ac[k] * w;
    }
    sub(x, pt, r);
    return sqrt(dot(r, r));
}

/* The extreme vertex of one side: replaces cur when x lies outside ball(p, s, t, cur). */
static uint32_t extreme(const fl_mesh *m, const double *p, const double *s, const double *t,
                        uint32_t cur, uint32_t x)
{
    if (cur == FL_HAL3_NONE) return x;
    int o = fl_orient3d(p, s, t, vx(m, cur));
    return fl_insphere(p, s, t, vx(m, cur), vx(m, x)) * o < 0 ? x : cur;
}

/* Signed radius (Def. 7.1): positive when the centre is on q's side of the corners' plane. */
static double signed_radius(const double *p, const double *n, const double *q, const double *c)
{
    double pc[3], pq[3];
    sub(c, p, pc), sub(q, p, pq);
    double r = sqrt(dot(pc, pc));
    return dot(n, pc) * dot(n, pq) >= 0 ? r : -r;
}

/* Def. 7.6: the largest distance from the plane of a point of the ball on side `side`. */
static double width(const double *ball, const double *p, const double *unit_n, int side)
{
    double pc[3];
    sub(ball, p, pc);
    return sqrt(ball[3]) + side * dot(unit_n, pc);
}

typedef struct vset {
    uint32_t *v;
    size_t n;
} vset;

uint32_t hal3_flintstone(hal3_work *w, fl_hal3_node *nd, const hal3_piece *pc)
{
    const fl_mesh *m = w->mesh;
    const double *P = vx(m, nd->v[0]), *S = vx(m, nd->v[1]), *T = vx(m, nd->v[2]);
    uint32_t loop_st = ++w->stamp, seen = ++w->stamp;
    for (size_t i = 0; i < pc->nl; i++)
        w->vert_block[pc->loop[i]] = loop_st;
    /* The part's vertices go to w->queue's sibling buffer pred (free outside Dijkstra). */
    vset V = {w->pred, 0};
    uint32_t qa[2] = {FL_HAL3_NONE, FL_HAL3_NONE}, qi[2] = {FL_HAL3_NONE, FL_HAL3_NONE};
    uint32_t any_interior = FL_HAL3_NONE;
    int degenerate = fl_triangle_degenerate(P, S, T);
    for (size_t i = 0; i < pc->nf; i++)
        for (int k = 0; k < 3; k++) {
            uint32_t x = m->tri[3 * (size_t)pc->faces[i] + k];
            if (w->vert_mark[x] == seen) continue;
            w->vert_mark[x] = seen;
            V.v[V.n++] = x;
            int interior = w->vert_block[x] != loop_st;
            if (interior && any_interior == FL_HAL3_NONE) any_interior = x;
            if (degenerate) continue;
            int o = fl_orient3d(P, S, T, vx(m, x));
            if (o == 0) continue;
            int sd = o > 0 ? 0 : 1;
            qa[sd] = extreme(m, P, S, T, qa[sd], x);
            if (interior) qi[sd] = extreme(m, P, S, T, qi[sd], x);
        }
    double a[3], b[3], n[3], un[3];
    sub(S, P, a), sub(T, P, b), cross(a, b, n);
    double nl = sqrt(dot(n, n));
    for (int k = 0; k < 3; k++)
        un[k] = nl > 0 ? n[k] / nl : 0;
    nd->width[0] = nd->width[1] = 0;
    nd->side = 0;
    /* fl_orient3d(P,S,T,x) > 0 means x below the plane, i.e. on the side of -n. */
    if (V.n == 0) { /* no surface: an empty flintstone (a ball no point is inside) */
        nd->kind = FL_HAL3_BALL;
        memcpy(nd->ball[0], P, 3 * sizeof(double));
        nd->ball[0][3] = -1;
        nd->error = 0;
        return FL_HAL3_NONE;
    }
    if (degenerate || (qa[0] == FL_HAL3_NONE && qa[1] == FL_HAL3_NONE)) {
        double c[3] = {0, 0, 0};
        for (size_t i = 0; i < V.n; i++)
            for (int k = 0; k < 3; k++)
                c[k] += vx(m, V.v[i])[k] / (double)V.n;
        nd->kind = FL_HAL3_BALL;
        memcpy(nd->ball[0], c, sizeof c);
    } else if (qa[0] == FL_HAL3_NONE || qa[1] == FL_HAL3_NONE) {
        int sd = qa[0] != FL_HAL3_NONE ? 0 : 1;
        nd->kind = FL_HAL3_BALL_HALFSPACE;
        nd->side = sd == 0 ? 1 : -1;
        circumcentre(P, S, T, vx(m, qa[sd]), nd->ball[0]);
    } else {
        double cq[3], cr[3];
        circumcentre(P, S, T, vx(m, qa[0]), cq);
        circumcentre(P, S, T, vx(m, qa[1]), cr);
        double rq = signed_radius(P, n, vx(m, qa[0]), cq);
        double rr = signed_radius(P, n, vx(m, qa[1]), cr);
        /* Def. 7.2: union when both radii are positive or the negative one is smaller. */
        int uni =
            (rq > 0 && rr > 0) || (rq < 0 && rr > 0 && -rq < rr) || (rr < 0 && rq > 0 && -rr < rq);
        memcpy(nd->ball[0], cq, sizeof cq);
        memcpy(nd->ball[1], cr, sizeof cr);
        nd->kind = uni ? FL_HAL3_BALL_UNION : FL_HAL3_TWO_BALLS;
    }
    /* The circumcentre is a floating construction: for a corner triangle seen almost edge-on
     * from v_q (one vertex 1e20 away) its denominator rounds to 0 and the centre came out NaN
     * with radius max(0, NaN) = 0: a ball that every NaN comparison called "may contain", so
     * it pruned nothing, and NaN widths (seen while checking a fuzz_hal3 report). Any finite
     * centre is correct, since the radius is measured to every vertex: use their centroid. */
    for (int j = 0; j < 2; j++) {
        double *c = nd->ball[j];
        if (isfinite(c[0]) && isfinite(c[1]) && isfinite(c[2])) continue;
        c[0] = c[1] = c[2] = 0;
        for (size_t i = 0; i < V.n; i++)
            for (int k = 0; k < 3; k++)
                c[k] += vx(m, V.v[i])[k] / (double)V.n;
    }
    /* Radii: the largest squared distance to the vertices each ball must hold. */
    nd->ball[0][3] = nd->ball[1][3] = 0;
    for (size_t i = 0; i < V.n; i++) {
        const double *x = vx(m, V.v[i]);
        int below = nd->kind == FL_HAL3_BALL_UNION && fl_orient3d(P, S, T, x) < 0;
        double d0 = fl_hal3_d2(nd->ball[0], x), d1 = fl_hal3_d2(nd->ball[1], x);
        if (nd->kind != FL_HAL3_BALL_UNION || !below) nd->ball[0][3] = fmax(nd->ball[0][3], d0);
        if (nd->kind == FL_HAL3_TWO_BALLS || (nd->kind == FL_HAL3_BALL_UNION && below))
            nd->ball[1][3] = fmax(nd->ball[1][3], d1);
    }
    if (nd->kind == FL_HAL3_BALL_UNION) {
        for (size_t i = 0; i < pc->nf && nd->kind == FL_HAL3_BALL_UNION; i++) {
            int in[2] = {1, 1};
            for (int k = 0; k < 3; k++)
                for (int j = 0; j < 2; j++)
                    if (fl_hal3_d2(nd->ball[j], vx(m, m->tri[3 * (size_t)pc->faces[i] + k])) >
                        nd->ball[j][3])
                        in[j] = 0;
            if (!in[0] && !in[1]) nd->kind = FL_HAL3_TWO_BALLS;
        }
        if (nd->kind == FL_HAL3_TWO_BALLS)
            for (size_t i = 0; i < V.n; i++)
                for (int j = 0; j < 2; j++)
                    nd->ball[j][3] = fmax(nd->ball[j][3], fl_hal3_d2(nd->ball[j], vx(m, V.v[i])));
    }
    if (nd->kind == FL_HAL3_BALL_HALFSPACE) {
        nd->width[0] = width(nd->ball[0], P, un, -nd->side);
    } else if (nd->kind == FL_HAL3_TWO_BALLS || nd->kind == FL_HAL3_BALL_UNION) {
        nd->width[0] = width(nd->ball[0], P, un, -1); /* ball of v_q: orient3d > 0, side -n */
        nd->width[1] = width(nd->ball[1], P, un, 1);
    }
    double e = 0;
    for (size_t i = 0; i < V.n; i++)
        e = fmax(e, point_triangle_distance(vx(m, V.v[i]), P, S, T));
    nd->error = e * (1 + 1e-9);
    /* The three-split vertex: v_q or v_r among the interior vertices, the larger signed
     * radius (§7.3.2). */
    if (qi[0] != FL_HAL3_NONE && qi[1] != FL_HAL3_NONE) {
        double c0[3], c1[3];
        circumcentre(P, S, T, vx(m, qi[0]), c0);
        circumcentre(P, S, T, vx(m, qi[1]), c1);
        return signed_radius(P, n, vx(m, qi[0]), c0) >= signed_radius(P, n, vx(m, qi[1]), c1)
                   ? qi[0]
                   : qi[1];
    }
    if (qi[0] != FL_HAL3_NONE) return qi[0];
    if (qi[1] != FL_HAL3_NONE) return qi[1];
    return any_interior;
}

void hal3_leaf_ball(const fl_mesh *m, fl_hal3_node *nd)
{
    double *c = nd->ball[0];
    for (int k = 0; k < 3; k++)
        c[k] = (vx(m, nd->v[0])[k] + vx(m, nd->v[1])[k] + vx(m, nd->v[2])[k]) / 3;
    c[3] = 0;
    for (int j = 0; j < 3; j++)
        c[3] = fmax(c[3], fl_hal3_d2(c, vx(m, nd->v[j])));
    nd->kind = FL_HAL3_LEAF;
    nd->error = 0;
}

int fl_hal3_flintstone_may_contain(const fl_hal3 *hal, uint32_t node, const double *x)
{
    const fl_hal3_node *nd = &hal->nodes[node];
    int out0 = fl_hal3_outside_ball(nd->ball[0], x);
    switch (nd->kind) {
    case FL_HAL3_TWO_BALLS:
        return !out0 && !fl_hal3_outside_ball(nd->ball[1], x);
    case FL_HAL3_BALL_UNION:
        return !out0 || !fl_hal3_outside_ball(nd->ball[1], x);
    case FL_HAL3_BALL_HALFSPACE:
        return !out0 && fl_orient3d(vx(&hal->mesh, nd->v[0]), vx(&hal->mesh, nd->v[1]),
                                    vx(&hal->mesh, nd->v[2]), x) *
                                nd->side >=
                            0;
    default:
        return !out0;
    }
}

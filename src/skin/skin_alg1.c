/* Algorithm 1 of Cheng & Tan §4.2: the protecting balls of an edge or a triangle are added at
 * positive restricted Voronoi vertices until the element is covered.
 *
 * For an element sigma with the balls X of its boundary (and those already added on it), the
 * restricted Voronoi (power) complex V_X(sigma) has the cells v_b(sigma) = {x in sigma :
 * pi_b(x) <= pi_b'(x) for all b' in X}, pi_b(x) = |x - z_b|^2 - w_b. All centres lie in sigma's
 * line or plane, so the cells are intervals (edge) or convex polygons (triangle): sigma cut by
 * one half-line/half-plane per other ball. A vertex u of v_b(sigma) is positive when
 * pi_b(u) > 0: then u is outside every ball (b minimises the power at u), and by
 * Proposition 10 sigma is covered by X exactly when no vertex is positive. Each loop adds the
 * ball (u, r^2) with r = min(gamma lgs(u), rmax) at the vertex of largest power (the farthest
 * from being covered; the paper allows any) and updates only the cells its half-plane cuts.
 * Lemma 12 gives termination: positive vertices stay in the compact part of sigma outside the
 * boundary balls, where lgs is bounded below. Radii < lgs/2 give C1 and Proposition 10 C2.
 *
 * Rounding: a vertex counts as positive when pi_b(u) > 1e-9 w_b (plus a rounding term), i.e.
 * the element is covered up to 5e-10 of each ball's radius. A positive vertex on the element's
 * boundary would mean the boundary's balls do not cover it; that is reported, not patched. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "skin/skin_sampler.h"

/* MAXV: a cell next to many small balls near an edge has many sides (40 was exceeded on the
 * cube at eps 0.015); more fails with FL_ERR_ALGORITHM. */
enum { MAXV = 96, ELEMENT_CAP = 200000 };

typedef struct cell2 {
    double c[2], w; /* centre in the triangle's 2D frame, weight */
    double R;       /* largest distance from c to a vertex of the cell */
    double pmax;    /* largest power pi_b over the cell's vertices; -HUGE_VAL when empty */
    int n, arg;     /* vertex count, vertex of power pmax */
    double v[MAXV][2];
} cell2;

static double tolerance(double w, double len)
{
    return 1e-9 * w + 1e-14 * len * sqrt(w);
}

static fl_status element_cap(size_t n, fl_error *err)
{
    if (n < ELEMENT_CAP) return FL_OK;
    return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                   "skin: more than %d protecting balls on one mesh element (Algorithm 1); the "
                   "local gap size is too small for this epsilon",
                   (int)ELEMENT_CAP);
}

/* ---- edges: a 1D power diagram on [0, len] ---- */

typedef struct cell1 {
    double c, w, lo, hi;
} cell1;

/* Cuts cell a by ball b: pi_a <= pi_b  <=>  2 x (c_b - c_a) <= c_b^2 - c_a^2 + w_a - w_b. */
static void clip1(cell1 *a, const cell1 *b)
{
    double d = b->c - a->c, rhs = (b->c - a->c) * (b->c + a->c) + a->w - b->w;
    if (d > 0)
        a->hi = fmin(a->hi, rhs / (2 * d));
    else if (d < 0)
        a->lo = fmax(a->lo, rhs / (2 * d));
    else if (rhs < 0)
        a->hi = -HUGE_VAL; /* same centre, smaller weight: hidden */
}

static double power1(const cell1 *a, double x)
{
    return (x - a->c) * (x - a->c) - a->w;
}

fl_status skin_alg1_edge(skin_sampler *s, size_t e, fl_error *err)
{
    const uint32_t *ids = s->edge + 2 * e;
    const double *a = s->m->xyz + 3 * (size_t)ids[0], *b = s->m->xyz + 3 * (size_t)ids[1];
    double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double len = sqrt(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
    const double *bb = s->balls.data;
    fl_vec cells;
    fl_vec_init(&cells, sizeof(cell1));
    cell1 ends[2] = {{0, bb[4 * (size_t)s->vball[ids[0]] + 3], 0, len},
                     {len, bb[4 * (size_t)s->vball[ids[1]] + 3], 0, len}};
    clip1(&ends[0], &ends[1]);
    clip1(&ends[1], &ends[0]);
    fl_status st = FL_OK;
    if (fl_vec_push(&cells, ends, 2)) goto nomem;
    for (;;) {
        cell1 *cl = cells.data;
        size_t best = SIZE_MAX;
        double bestp = 0, u = 0;
        for (size_t i = 0; i < cells.count; i++) {
            if (!(cl[i].lo <= cl[i].hi)) continue;
            double tol = tolerance(cl[i].w, len);
            double p0 = power1(&cl[i], cl[i].lo), p1 = power1(&cl[i], cl[i].hi);
            double p = fmax(p0, p1);
            if (p > tol && p > bestp) {
                bestp = p;
                best = i;
                u = p0 >= p1 ? cl[i].lo : cl[i].hi;
            }
        }
        if (best == SIZE_MAX) break;
        if (!(u > 1e-12 * len && u < len * (1 - 1e-12))) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                         "skin: Algorithm 1: an endpoint of edge %zu is not covered by its vertex "
                         "ball (power %g)",
                         e, bestp);
            break;
        }
        if ((st = skin_sampler_tick(s, 0, 1, err)) || (st = element_cap(cells.count, err))) break;
        double p[3] = {a[0] + u / len * ab[0], a[1] + u / len * ab[1], a[2] + u / len * ab[2]};
        double r = skin_sampler_radius(s, p, 1, ids, 0);
        if ((st = skin_sampler_push(s, p, r, 1, (uint32_t)e, err))) break;
        cell1 nc = {u, r * r, 0, len};
        for (size_t i = 0; i < cells.count; i++) {
            clip1(&nc, &cl[i]);
            clip1(&cl[i], &nc);
        }
        if (fl_vec_push(&cells, &nc, 1)) goto nomem;
    }
    fl_vec_free(&cells);
    return st;
nomem:
    fl_vec_free(&cells);
    return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (Algorithm 1)");
}

/* ---- triangles: a 2D power diagram clipped to the triangle ---- */

static void cell_measure(cell2 *c)
{
    c->R = 0;
    c->pmax = -HUGE_VAL;
    c->arg = -1;
    for (int k = 0; k < c->n; k++) {
        double dx = c->v[k][0] - c->c[0], dy = c->v[k][1] - c->c[1], d2 = dx * dx + dy * dy;
        c->R = fmax(c->R, sqrt(d2));
        if (d2 - c->w > c->pmax) {
            c->pmax = d2 - c->w;
            c->arg = k;
        }
    }
}

/* Cuts cell a by the half-plane pi_a <= pi_b, i.e. x.d <= d.(c_a + c_b)/2 + (w_a - w_b)/2 with
 * d = c_b - c_a (Sutherland-Hodgman on a convex polygon). 1 when the cell changed, -1 when
 * it would exceed MAXV vertices. */
static int clip2(cell2 *a, const cell2 *b)
{
    double d[2] = {b->c[0] - a->c[0], b->c[1] - a->c[1]};
    double h =
        d[0] * 0.5 * (a->c[0] + b->c[0]) + d[1] * 0.5 * (a->c[1] + b->c[1]) + 0.5 * (a->w - b->w);
    double sv[MAXV];
    int out = 0;
    for (int k = 0; k < a->n; k++) {
        sv[k] = d[0] * a->v[k][0] + d[1] * a->v[k][1] - h;
        out += sv[k] > 0;
    }
    if (out == 0) return 0;
    double nv[MAXV + 1][2];
    int m = 0;
    for (int k = 0; k < a->n && m <= MAXV; k++) {
        int k1 = (k + 1) % a->n;
        if (sv[k] <= 0) {
            nv[m][0] = a->v[k][0];
            nv[m++][1] = a->v[k][1];
        }
        if ((sv[k] <= 0) != (sv[k1] <= 0) && m <= MAXV) {
            double t = sv[k] / (sv[k] - sv[k1]);
            nv[m][0] = a->v[k][0] + t * (a->v[k1][0] - a->v[k][0]);
            nv[m++][1] = a->v[k][1] + t * (a->v[k1][1] - a->v[k][1]);
        }
    }
    if (m > MAXV) return -1;
    memcpy(a->v, nv, (size_t)m * sizeof nv[0]);
    a->n = m;
    cell_measure(a);
    return 1;
}

/* 0 when b's half-plane cannot cut cell a: every vertex x of a has |x - c_a| <= R, so
 * pi_b(x) >= (d - R)^2 - w_b when d = |c_a - c_b| > R, and pi_a(x) <= R^2 - w_a. */
static int may_cut(const cell2 *a, const cell2 *b)
{
    if (a->n == 0) return 0;
    double dx = a->c[0] - b->c[0], dy = a->c[1] - b->c[1], d = sqrt(dx * dx + dy * dy);
    return !(d > a->R && (d - a->R) * (d - a->R) - b->w >= a->R * a->R - a->w);
}

typedef struct frame2 {
    double o[3], e1[3], e2[3], q[3][2], len; /* origin, basis, 2D corners, longest side */
} frame2;

static void frame_of(const fl_mesh *m, const uint32_t *t, frame2 *fr)
{
    const double *p0 = m->xyz + 3 * (size_t)t[0], *p1 = m->xyz + 3 * (size_t)t[1],
                 *p2 = m->xyz + 3 * (size_t)t[2];
    double u[3], v[3], n1 = 0, uv = 0;
    for (int k = 0; k < 3; k++) {
        fr->o[k] = p0[k];
        u[k] = p1[k] - p0[k];
        v[k] = p2[k] - p0[k];
        n1 += u[k] * u[k];
    }
    n1 = sqrt(n1);
    for (int k = 0; k < 3; k++) {
        fr->e1[k] = u[k] / n1;
        uv += v[k] * fr->e1[k];
    }
    double n2 = 0;
    for (int k = 0; k < 3; k++) {
        fr->e2[k] = v[k] - uv * fr->e1[k];
        n2 += fr->e2[k] * fr->e2[k];
    }
    n2 = sqrt(n2);
    for (int k = 0; k < 3; k++)
        fr->e2[k] /= n2;
    fr->q[0][0] = fr->q[0][1] = 0;
    fr->q[1][0] = n1;
    fr->q[1][1] = 0;
    fr->q[2][0] = uv;
    fr->q[2][1] = n2;
    double l2 = sqrt((uv - n1) * (uv - n1) + n2 * n2), l3 = sqrt(uv * uv + n2 * n2);
    fr->len = fmax(n1, fmax(l2, l3));
}

static void to2d(const frame2 *fr, const double *p, double *x)
{
    double d[3] = {p[0] - fr->o[0], p[1] - fr->o[1], p[2] - fr->o[2]};
    x[0] = d[0] * fr->e1[0] + d[1] * fr->e1[1] + d[2] * fr->e1[2];
    x[1] = d[0] * fr->e2[0] + d[1] * fr->e2[1] + d[2] * fr->e2[2];
}

/* Distance from x to the triangle's boundary (x inside). */
static double boundary_gap(const frame2 *fr, const double *x)
{
    double g = HUGE_VAL;
    for (int j = 0; j < 3; j++) {
        const double *a = fr->q[j], *b = fr->q[(j + 1) % 3];
        double ex = b[0] - a[0], ey = b[1] - a[1];
        g = fmin(g, fabs(ex * (x[1] - a[1]) - ey * (x[0] - a[0])) / sqrt(ex * ex + ey * ey));
    }
    return g;
}

/* Adds the ball (c, w) to the diagram: its cell is the triangle cut by every other ball, and it
 * cuts the cells its half-plane reaches. */
static fl_status insert2(fl_vec *cells, const frame2 *fr, const double *c, double w, fl_error *err)
{
    cell2 nc;
    nc.c[0] = c[0];
    nc.c[1] = c[1];
    nc.w = w;
    nc.n = 3;
    memcpy(nc.v, fr->q, sizeof fr->q);
    cell_measure(&nc);
    cell2 *cl = cells->data;
    int bad = 0;
    for (size_t i = 0; i < cells->count && nc.n > 0; i++)
        if (may_cut(&nc, &cl[i])) bad |= clip2(&nc, &cl[i]) < 0;
    for (size_t i = 0; i < cells->count; i++)
        if (may_cut(&cl[i], &nc)) bad |= clip2(&cl[i], &nc) < 0;
    if (bad)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "skin: Algorithm 1: a restricted power cell with more than %d vertices",
                       (int)MAXV);
    if (fl_vec_push(cells, &nc, 1))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (Algorithm 1)");
    return FL_OK;
}

/* The boundary balls of triangle f (its vertex balls and its edges' balls) into bl. */
static int boundary_balls(const skin_sampler *s, const uint32_t *t, fl_vec *bl)
{
    bl->count = 0;
    for (int j = 0; j < 3; j++) {
        size_t vb = s->vball[t[j]], e = skin_sampler_edge_index(s, t[j], t[(j + 1) % 3]);
        if (fl_vec_push(bl, &vb, 1)) return 1;
        for (size_t i = s->edge_first[e]; i < s->edge_first[e + 1]; i++)
            if (fl_vec_push(bl, &i, 1)) return 1;
    }
    return 0;
}

static fl_status fill_triangle(skin_sampler *s, size_t f, const frame2 *fr, fl_vec *cells,
                               fl_error *err)
{
    const uint32_t *t = s->m->tri + 3 * f;
    for (;;) {
        cell2 *cl = cells->data;
        size_t best = SIZE_MAX;
        double bestp = 0;
        for (size_t i = 0; i < cells->count; i++)
            if (cl[i].pmax > tolerance(cl[i].w, fr->len) && cl[i].pmax > bestp) {
                bestp = cl[i].pmax;
                best = i;
            }
        if (best == SIZE_MAX) return FL_OK;
        double u[2] = {cl[best].v[cl[best].arg][0], cl[best].v[cl[best].arg][1]};
        if (!(boundary_gap(fr, u) > 1e-12 * fr->len))
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                           "skin: Algorithm 1: a point of the boundary of triangle %zu is not "
                           "covered by its edges' balls (power %g)",
                           f, bestp);
        fl_status st = skin_sampler_tick(s, 0, 1, err);
        if (!st) st = element_cap(cells->count, err);
        if (st) return st;
        double p[3];
        for (int k = 0; k < 3; k++)
            p[k] = fr->o[k] + u[0] * fr->e1[k] + u[1] * fr->e2[k];
        double r = skin_sampler_radius(s, p, 2, t, f);
        if ((st = skin_sampler_push(s, p, r, 2, (uint32_t)f, err))) return st;
        if ((st = insert2(cells, fr, u, r * r, err))) return st;
    }
}

fl_status skin_alg1_triangle(skin_sampler *s, size_t f, fl_vec *bl, fl_error *err)
{
    const uint32_t *t = s->m->tri + 3 * f;
    frame2 fr;
    frame_of(s->m, t, &fr);
    if (boundary_balls(s, t, bl))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (Algorithm 1)");
    fl_vec cells;
    fl_vec_init(&cells, sizeof(cell2));
    fl_status st = FL_OK;
    const size_t *ids = bl->data;
    for (size_t i = 0; i < bl->count && !st; i++) {
        const double *b = (const double *)s->balls.data + 4 * ids[i];
        double x[2];
        to2d(&fr, b, x);
        st = insert2(&cells, &fr, x, b[3], err);
    }
    if (!st) st = fill_triangle(s, f, &fr, &cells, err);
    fl_vec_free(&cells);
    return st;
}

/* A bound on the power face nu_X of a simplex whose Voronoi vertices do not give one (round 14).
 *
 * The index lists a simplex X near its mixed cell mu_X = (1-t) X + t nu_X, cut to its reach
 * box R (skin_function.c, reg_box). When a tetrahedron around X is a sliver (its Voronoi vertex
 * is decided by rounding) or X lies on the hull, the box of nu_X is not known from the vertices
 * and X used to be listed in the whole reach box. On B* of the npm bunny that was 2 million
 * vertices, edges and triangles with reach boxes of side ~1 (the interior balls are large):
 * a point of the bunny lay in 81 000 registration boxes, and each scan of the walk's fallback
 * evaluated ~12 000 candidates whose z* lies in their simplex (docs/skin.md, round 14).
 *
 * nu_X itself does not depend on the sliver's vertex: it is the part of aff nu_X (the points of
 * equal power to the balls of X: all of space for a vertex, the plane through the focus
 * orthogonal to an edge, the line through the focus along a triangle's normal) where no ball
 * has a smaller power distance than X's, so it lies in
 *     P = { v in aff nu_X : pi_b(v) >= pi_X(v) for every ball b of X's link } ,
 * a superset (the link is a subset of the balls). Only the part where (1-t) a + t v lies in R
 * for some a in X matters, i.e. v in the box V = (R - (1-t) box(X)) / t. This file clips V by
 * the link half-spaces, relaxed by a bound on their rounding, in coordinates on aff nu_X
 * (dimension 3 - k: a convex polyhedron, polygon or interval) and returns the box of what is
 * left, padded for the rounding of the construction. The sliver's half-spaces are harmless
 * here: each is a well-defined half-space (a bisector of two distinct balls), only the vertex
 * where three of them meet is ill-conditioned, and the box of the clipped region does not ask
 * for it. An empty region means that mu_X misses R: X is never the minimiser of a G < 0. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "skin/skin_internal.h"

/* Vertices of the clipped region: one face of the polyhedron has at most as many vertices as
 * there are half-spaces, the box's 6 plus the link; links longer than this are not clipped. */
#define CLIP_MAX_LINK 250
#define CLIP_MAX_PLANES (CLIP_MAX_LINK + 6)
#define CLIP_MAX_VERTS (2 * CLIP_MAX_PLANES)

int skin_clip_off;

typedef struct clip_plane {
    double n[3], c; /* n . s <= c in the parameters s of aff nu_X */
} clip_plane;

static double dotn(const double *u, const double *v, int d)
{
    double r = 0;
    for (int i = 0; i < d; i++)
        r += u[i] * v[i];
    return r;
}

/* Interval [lo, hi] clipped by the planes (d = 1). 0 when empty. */
static int clip_interval(const clip_plane *pl, int np, double *lo, double *hi)
{
    for (int i = 0; i < np; i++) {
        double a = pl[i].n[0], c = pl[i].c;
        if (a > 0)
            *hi = fmin(*hi, c / a);
        else if (a < 0)
            *lo = fmax(*lo, c / a);
        else if (c < 0)
            return 0;
        if (!(*lo <= *hi)) return 0;
    }
    return 1;
}

/* Appends x to the cap points unless it is one of them up to rounding (each cut edge is met
 * from both of its faces). */
static void add_cut(double (*cut)[3], int *ncut, const double *x)
{
    double tol = 1e-12 * (1 + fabs(x[0]) + fabs(x[1]) + fabs(x[2]));
    for (int i = 0; i < *ncut; i++)
        if (fabs(cut[i][0] - x[0]) <= tol && fabs(cut[i][1] - x[1]) <= tol &&
            fabs(cut[i][2] - x[2]) <= tol)
            return;
    if (*ncut < CLIP_MAX_VERTS)
        memcpy(cut[(*ncut)++], x, sizeof cut[0]);
    else
        *ncut = CLIP_MAX_VERTS + 1; /* full: the caller gives up */
}

/* Sutherland-Hodgman: the convex polygon p[0..n) (dimension d = 2 or 3 coordinates) cut by
 * n.s <= c into q; returns the new vertex count, -1 when q would overflow. The points cut on
 * the plane are appended to cut (when not NULL) for the cap face of the polyhedron. */
static int clip_polygon(const double (*p)[3], int n, const clip_plane *pl, int d, double (*q)[3],
                        double (*cut)[3], int *ncut)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        const double *a = p[i], *b = p[(i + 1) % n];
        double da = dotn(pl->n, a, d) - pl->c, db = dotn(pl->n, b, d) - pl->c;
        if (m + 2 > CLIP_MAX_VERTS) return -1;
        if (da <= 0) memcpy(q[m++], a, sizeof q[0]);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
            double r = da / (da - db), x[3] = {0, 0, 0};
            for (int j = 0; j < d; j++)
                x[j] = a[j] + r * (b[j] - a[j]);
            memcpy(q[m++], x, sizeof x);
            if (cut) add_cut(cut, ncut, x);
        } else if (cut && da == 0) {
            add_cut(cut, ncut, a);
        }
    }
    return m;
}

typedef struct clip_poly3 {
    int faces;
    int start[CLIP_MAX_PLANES + 1]; /* face f: vert[start[f] .. start[f + 1]) */
    double (*vert)[3];
} clip_poly3;

/* u, w: an orthonormal basis of the plane orthogonal to the unit vector n. */
static void plane_basis(const double n[3], double u[3], double w[3])
{
    double h[3] = {fabs(n[0]) < 0.6 ? 1 : 0, fabs(n[0]) < 0.6 ? 0 : 1, 0};
    double hd = dotn(h, n, 3);
    for (int c = 0; c < 3; c++)
        u[c] = h[c] - hd * n[c];
    double ul = sqrt(dotn(u, u, 3));
    for (int c = 0; c < 3; c++)
        u[c] /= ul;
    w[0] = n[1] * u[2] - n[2] * u[1];
    w[1] = n[2] * u[0] - n[0] * u[2];
    w[2] = n[0] * u[1] - n[1] * u[0];
}

static double sort_key_angle(const double *x, const double *o, const double *u, const double *w)
{
    double d[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
    return atan2(dotn(d, w, 3), dotn(d, u, 3));
}

typedef struct angle_item {
    double key;
    int idx;
} angle_item;

static int cmp_angle(const void *pa, const void *pb)
{
    double a = ((const angle_item *)pa)->key, b = ((const angle_item *)pb)->key;
    return a < b ? -1 : a > b;
}

/* Scratch space of the clipping, allocated once for all simplices. */
typedef struct clip_ws {
    clip_poly3 P;
    double (*out)[3], (*tmp)[3], (*cut)[3];
    int outstart[CLIP_MAX_PLANES + 1];
    clip_plane pl[CLIP_MAX_PLANES];
} clip_ws;
#define CLIP_CAP (CLIP_MAX_VERTS * 4)

/* The convex polyhedron w->P cut by one plane: every face clipped, then the cap face from the
 * points cut on the plane, ordered by angle round their centroid. 1 when a polyhedron is left,
 * 0 when all of it lies outside the plane, -1 when it degenerated or the scratch is full (the
 * caller then keeps the reach box). */
static int clip_poly3_plane(clip_ws *w, const clip_plane *pl)
{
    clip_poly3 *P = &w->P;
    int ncut = 0, faces = 0, m = 0;
    w->outstart[0] = 0;
    for (int f = 0; f < P->faces; f++) {
        int n = P->start[f + 1] - P->start[f];
        int k = clip_polygon((const double(*)[3])(P->vert + P->start[f]), n, pl, 3, w->tmp,
                             w->cut, &ncut);
        if (k < 0 || ncut > CLIP_MAX_VERTS) return -1;
        if (k < 3) continue;
        if (m + k > CLIP_CAP || faces >= CLIP_MAX_PLANES) return -1;
        memcpy(w->out + m, w->tmp, (size_t)k * sizeof w->out[0]);
        m += k;
        w->outstart[++faces] = m;
    }
    if (faces == 0 && ncut == 0) return 0;
    if (ncut >= 3) {
        if (faces >= CLIP_MAX_PLANES || m + ncut > CLIP_CAP) return -1;
        double o[3] = {0, 0, 0}, u[3], v[3], nl = sqrt(dotn(pl->n, pl->n, 3));
        for (int i = 0; i < ncut; i++)
            for (int c = 0; c < 3; c++)
                o[c] += w->cut[i][c] / ncut;
        double nn[3] = {pl->n[0] / nl, pl->n[1] / nl, pl->n[2] / nl};
        plane_basis(nn, u, v);
        angle_item it[CLIP_MAX_VERTS];
        for (int i = 0; i < ncut; i++) {
            it[i].key = sort_key_angle(w->cut[i], o, u, v);
            it[i].idx = i;
        }
        qsort(it, (size_t)ncut, sizeof it[0], cmp_angle);
        for (int i = 0; i < ncut; i++)
            memcpy(w->out[m++], w->cut[it[i].idx], sizeof w->out[0]);
        w->outstart[++faces] = m;
    }
    if (faces < 4) return -1;
    P->faces = faces;
    memcpy(P->start, w->outstart, (size_t)(faces + 1) * sizeof P->start[0]);
    memcpy(P->vert, w->out, (size_t)m * sizeof w->out[0]);
    return 1;
}

/* The cube [lo, hi] clipped by the planes (d = 3); lo/hi become the box of what is left. 1, or
 * 0 (empty) or -1 as clip_poly3_plane. */
static int clip_cube(clip_ws *w, const clip_plane *pl, int np, double lo[3], double hi[3])
{
    clip_poly3 *P = &w->P;
    static const int quad[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                   {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    P->faces = 6;
    for (int f = 0; f < 6; f++) {
        P->start[f] = 4 * f;
        for (int j = 0; j < 4; j++) {
            int corner = quad[f][j];
            for (int c = 0; c < 3; c++)
                P->vert[4 * f + j][c] = corner >> c & 1 ? hi[c] : lo[c];
        }
    }
    P->start[6] = 24;
    int r = 1;
    for (int i = 0; i < np && r == 1; i++)
        r = clip_poly3_plane(w, pl + i);
    if (r != 1) return r;
    for (int c = 0; c < 3; c++) {
        lo[c] = HUGE_VAL;
        hi[c] = -HUGE_VAL;
    }
    for (int v = 0; v < P->start[P->faces]; v++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], P->vert[v][c]);
            hi[c] = fmax(hi[c], P->vert[v][c]);
        }
    return 1;
}

/* The convex polygon (d = 2) of the square [lo, hi] clipped by the planes, its vertices left
 * in *poly (*n of them). 1, or 0 (empty) or -1 (degenerate, full) as clip_poly3_plane. */
static int clip_square(clip_ws *w, const clip_plane *pl, int np, const double lo[2],
                       const double hi[2], double (**poly)[3], int *n)
{
    double(*p)[3] = w->tmp, (*q)[3] = w->cut;
    double sq[4][2] = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
    *n = 4;
    for (int i = 0; i < 4; i++) {
        p[i][0] = sq[i][0];
        p[i][1] = sq[i][1];
        p[i][2] = 0;
    }
    for (int i = 0; i < np && *n >= 3; i++) {
        *n = clip_polygon((const double(*)[3])p, *n, pl + i, 2, q, NULL, NULL);
        if (*n < 0) return -1;
        double(*sw)[3] = p;
        p = q;
        q = sw;
    }
    *poly = p;
    return *n == 0 ? 0 : *n < 3 ? -1 : 1;
}

/* The box of P for simplex id (see the top of the file), in lo/hi; 1 with the box (lo > hi on
 * every axis when P is empty), 0 when it is not computed (not walkable, a tetrahedron, no
 * reach, a long link, a degenerate clip). */
static int clip_nu_box(const fl_skin_function *sk, size_t id, double margin, clip_ws *w,
                       double lo[3], double hi[3])
{
    const skin_simplex *s = &sk->simplex[id];
    if (!sk->walkable || s->k > 2) return 0;
    size_t l0 = sk->link_start[id], l1 = sk->link_start[id + 1];
    if (l1 - l0 > CLIP_MAX_LINK) return 0;
    double t = sk->t, a[3], e[3][3], f[3], g = margin * skin_reach(sk->balls, s, t);
    if (!(g > 0)) return 0;
    skin_frame(sk->balls, s, a, e);
    skin_focus(s, a, e, f);
    /* V, relative to a: (1-t) a' + t v in R = box(X) +- g for some a' in X */
    double xlo[3], xhi[3], vlo[3], vhi[3], scale = 0;
    for (int c = 0; c < 3; c++) {
        xlo[c] = xhi[c] = 0;
        for (int j = 0; j < s->k; j++) {
            xlo[c] = fmin(xlo[c], e[j][c]);
            xhi[c] = fmax(xhi[c], e[j][c]);
        }
        /* R - a = [xlo - g, xhi + g]; v - a = (x - a - (1-t)(a' - a)) / t */
        vlo[c] = (xlo[c] - g - (1 - t) * xhi[c]) / t;
        vhi[c] = (xhi[c] + g - (1 - t) * xlo[c]) / t;
        scale = fmax(scale, fmax(fabs(vlo[c]), fabs(vhi[c])));
    }
    if (!(isfinite(scale) && scale > 0)) return 0;
    /* aff nu_X - a = u0 + span(basis[0..d)) */
    int d = 3 - s->k;
    double u0[3] = {0, 0, 0}, basis[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    if (s->k >= 1) {
        for (int c = 0; c < 3; c++)
            u0[c] = f[c] - a[c];
        double n[3];
        if (s->k == 1) {
            double l = sqrt(e[0][0] * e[0][0] + e[0][1] * e[0][1] + e[0][2] * e[0][2]);
            for (int c = 0; c < 3; c++)
                n[c] = e[0][c] / l;
        } else {
            n[0] = e[0][1] * e[1][2] - e[0][2] * e[1][1];
            n[1] = e[0][2] * e[1][0] - e[0][0] * e[1][2];
            n[2] = e[0][0] * e[1][1] - e[0][1] * e[1][0];
            double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (int c = 0; c < 3; c++)
                n[c] /= l;
        }
        if (!(isfinite(n[0]) && isfinite(n[1]) && isfinite(n[2]))) return 0;
        if (s->k == 2) {
            memcpy(basis[0], n, sizeof n);
        } else { /* two unit vectors orthogonal to the edge direction n */
            plane_basis(n, basis[0], basis[1]);
        }
    }
    /* the half-spaces in the parameters s: V's six faces, then the link balls' (relaxed) */
    clip_plane *pl = w->pl;
    int np = 0;
    double ulen = fabs(u0[0]) + fabs(u0[1]) + fabs(u0[2]) + 3 * scale; /* >= |u| on V */
    for (int c = 0; c < 3; c++)
        for (int side = 0; side < 2; side++) { /* +-(u0 + B s)_c <= +-bound */
            double sg = side ? 1 : -1, bound = side ? vhi[c] : -vlo[c];
            for (int j = 0; j < d; j++)
                pl[np].n[j] = sg * basis[j][c];
            pl[np].c = bound - sg * u0[c];
            np++;
        }
    const double *b0 = sk->balls + 4 * (size_t)s->ball[0];
    for (size_t l = l0; l < l1; l++) {
        /* pi_b(v) - pi_X(v) = -2 u.e_b + |e_b|^2 - w_b + w_0 >= 0 with u = v - a */
        const double *b = sk->balls + 4 * (size_t)sk->link[l];
        double eb[3] = {b[0] - b0[0], b[1] - b0[1], b[2] - b0[2]};
        double e2 = dotn(eb, eb, 3), el = sqrt(e2);
        double rhs = e2 - b[3] + b0[3];
        /* rounding of the test, far above its ulps: |u| el for the products, the squares and
         * the weights themselves (not their difference: nearly equal balls) */
        double tol = 1e-9 * (2 * ulen * el + e2 + fabs(b[3]) + fabs(b0[3]));
        for (int j = 0; j < d; j++)
            pl[np].n[j] = 2 * dotn(eb, basis[j], 3);
        pl[np].c = rhs + tol - 2 * dotn(eb, u0, 3);
        np++;
    }
    /* the starting region: a cube / square / interval in the parameters holding V */
    double plo[3] = {0, 0, 0}, phi[3] = {0, 0, 0}, rad = 0, ctr[3];
    for (int c = 0; c < 3; c++) {
        ctr[c] = 0.5 * (vlo[c] + vhi[c]) - u0[c];
        rad += (vhi[c] - vlo[c]) * (vhi[c] - vlo[c]);
    }
    rad = 1.01 * sqrt(rad) / 2 + 1e-9 * ulen;
    for (int j = 0; j < d; j++) {
        double m = dotn(ctr, basis[j], 3);
        plo[j] = m - rad;
        phi[j] = m + rad;
    }
    /* the vertices of the clipped region in the parameters: the interval's ends, the
     * polygon's corners, the polyhedron's box (the identity basis: the box is exact) */
    double(*vert)[3] = NULL, ends[2][3] = {{0, 0, 0}, {0, 0, 0}};
    int nv = 2, r;
    if (d == 1) {
        r = clip_interval(pl, np, &plo[0], &phi[0]);
        ends[0][0] = plo[0];
        ends[1][0] = phi[0];
        vert = ends;
    } else if (d == 2) {
        r = clip_square(w, pl, np, plo, phi, &vert, &nv);
    } else {
        r = clip_cube(w, pl, np, plo, phi);
        memcpy(ends[0], plo, sizeof ends[0]);
        memcpy(ends[1], phi, sizeof ends[1]);
        vert = ends;
    }
    if (r < 0) return 0;
    if (!r) { /* nothing of nu_X within V: an empty box */
        for (int c = 0; c < 3; c++) {
            lo[c] = HUGE_VAL;
            hi[c] = -HUGE_VAL;
        }
        return 1;
    }
    /* back to space: a + u0 + sum_j s_j basis[j] over those vertices, padded */
    double pad = 1e-9 * (ulen + fabs(a[0]) + fabs(a[1]) + fabs(a[2]));
    for (int c = 0; c < 3; c++) {
        lo[c] = HUGE_VAL;
        hi[c] = -HUGE_VAL;
        for (int i = 0; i < nv; i++) {
            double x = a[c] + u0[c];
            for (int j = 0; j < d; j++)
                x += vert[i][j] * basis[j][c];
            lo[c] = fmin(lo[c], x);
            hi[c] = fmax(hi[c], x);
        }
        lo[c] -= pad;
        hi[c] += pad;
        if (!(lo[c] <= hi[c])) return 0;
    }
    return 1;
}

fl_status skin_clip_boxes(fl_skin_function *sk, double margin, fl_error *err)
{
    if (!sk->walkable) return FL_OK;
    clip_ws *w = malloc(sizeof *w);
    double(*buf)[3] = malloc(4 * (size_t)CLIP_CAP * sizeof *buf);
    if (!w || !buf) {
        free(w);
        free(buf);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    }
    w->P.vert = buf;
    w->out = buf + CLIP_CAP;
    w->tmp = buf + 2 * CLIP_CAP;
    w->cut = buf + 3 * CLIP_CAP;
    for (size_t i = 0; i < sk->simplex_count; i++) {
        skin_simplex *s = &sk->simplex[i];
        double lo[3], hi[3];
        if (s->box_exact || !clip_nu_box(sk, i, margin, w, lo, hi)) continue;
        memcpy(s->nu_lo, lo, sizeof lo);
        memcpy(s->nu_hi, hi, sizeof hi);
        s->box_exact = SKIN_BOX_CLIPPED;
    }
    free(w);
    free(buf);
    return FL_OK;
}

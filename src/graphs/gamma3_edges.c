/* Candidate generation for the non-Delaunay triangles (c1' < 0) of a 3D γ-graph from their
 * shortest edge (docs/gamma.md, "Construction", 3D; thesis ch. 3, Lemma 3.2).
 *
 * Let abc be accepted (c1' >= -kappa, kappa < 1) and non-Delaunay. Its symmetric lens
 * Λ = B(C - Tn) ∩ B(C + Tn) is empty (Lemma 3.2; C, R circumcentre and circumradius, n the unit
 * normal, g = 1/(1-kappa), T = R sqrt(g^2-1), both balls of radius gR through the circumcircle).
 * Take ab a shortest edge (length L, midpoint m, unit direction e). The angle at c is then at
 * most 60°, so C lies on c's side of ab at distance h = R cos(angle c) >= R/2 from m, in the
 * direction psi of the component of c - m orthogonal to e.
 *
 * Edge wedge (the proof is in docs/gamma.md): a point q = m + x e + w (w ⊥ e) of the open ball
 * B(m, L/2) lies in Λ as soon as w·(h psi ± T n) >= 0, i.e. as soon as the angle between w and
 * psi around the axis ab is at most atan(h/T), which is at least
 *     theta0 = atan(1 / (2 sqrt(g^2 - 1)))        (16.1° for kappa = 0.5).
 * So every point p of B(m, L/2) off the axis blocks every third vertex c whose angle around ab
 * is within theta0 of p's: an edge whose Gabriel-ball points block the whole circle of angles is
 * the shortest edge of no accepted triangle, and a third vertex must lie in an unblocked angle.
 *
 * The filters are floating and only ever keep a candidate when in doubt (shrunk ball, shrunk
 * angle, whole bins only, ill-conditioned angles ignored); each candidate is then decided by
 * gamma_triangle_check, the exact early-decided witness scan, so the output and its (c0', c1')
 * are the brute force's. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "graphs/gamma_internal.h"

#define G3_PI 3.14159265358979323846

typedef struct g3_ctx {
    const graph_grid *grid;
    const double *xyz;
    size_t n;
    const fl_gamma_params *params;
    double kappa;
    double theta;    /* blocking half-angle, theta0 shrunk by a safety margin */
    size_t bins;     /* angle bins around an edge, each at most theta/2 wide */
    double width;    /* 2 pi / bins */
    uint64_t *mask;  /* bins blocked for the current edge */
    size_t words;    /* 64-bit words of mask */
    size_t blocked;  /* bins set in mask */
    fl_vec ring, scan; /* point lists of grid rings */
} g3_ctx;

/* The current edge: endpoints, midpoint, squared length and an orthonormal frame (e, u1, u2). */
typedef struct g3_edge {
    uint32_t a, b;
    double m[3], e[3], u1[3], u2[3], len2;
} g3_edge;

static double dot3(const double *x, const double *y)
{
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

/* Returns 0 when the edge's frame is not finite (the filters are then skipped). */
static int edge_init(g3_edge *E, const double *xyz, uint32_t a, uint32_t b)
{
    const double *pa = xyz + 3 * (size_t)a, *pb = xyz + 3 * (size_t)b;
    E->a = a;
    E->b = b;
    double d[3];
    for (int k = 0; k < 3; k++) {
        E->m[k] = 0.5 * (pa[k] + pb[k]);
        d[k] = pb[k] - pa[k];
    }
    E->len2 = dot3(d, d);
    double len = sqrt(E->len2);
    if (!(len > 0) || !isfinite(E->len2)) return 0;
    for (int k = 0; k < 3; k++)
        E->e[k] = d[k] / len;
    /* u1: e crossed with the axis of e's smallest component, u2 = e x u1. */
    int s = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(E->e[k]) < fabs(E->e[s])) s = k;
    double axis[3] = {0, 0, 0};
    axis[s] = 1;
    E->u1[0] = E->e[1] * axis[2] - E->e[2] * axis[1];
    E->u1[1] = E->e[2] * axis[0] - E->e[0] * axis[2];
    E->u1[2] = E->e[0] * axis[1] - E->e[1] * axis[0];
    double l1 = sqrt(dot3(E->u1, E->u1));
    for (int k = 0; k < 3; k++)
        E->u1[k] /= l1;
    E->u2[0] = E->e[1] * E->u1[2] - E->e[2] * E->u1[1];
    E->u2[1] = E->e[2] * E->u1[0] - E->e[0] * E->u1[2];
    E->u2[2] = E->e[0] * E->u1[1] - E->e[1] * E->u1[0];
    return 1;
}

/* The angle of p around the edge's axis, in [-pi, pi]; NAN when it is ill-conditioned (p within
 * 1e-6 |p - m| of the axis, or not finite). Also returns |p - m|^2 in *dist2. */
static double axis_angle(const g3_edge *E, const double *p, double *dist2)
{
    double d[3] = {p[0] - E->m[0], p[1] - E->m[1], p[2] - E->m[2]};
    double x1 = dot3(d, E->u1), x2 = dot3(d, E->u2);
    *dist2 = dot3(d, d);
    double r2 = x1 * x1 + x2 * x2;
    if (!(r2 > 1e-12 * *dist2) || !isfinite(r2)) return NAN;
    return atan2(x2, x1);
}

static size_t bin_of(const g3_ctx *c, double angle)
{
    double k = floor((angle + G3_PI) / c->width);
    if (!(k >= 0)) return 0;
    return k >= (double)c->bins ? c->bins - 1 : (size_t)k;
}

static void mark_bin(g3_ctx *c, size_t k)
{
    uint64_t bit = (uint64_t)1 << (k & 63);
    if (!(c->mask[k >> 6] & bit)) {
        c->mask[k >> 6] |= bit;
        c->blocked++;
    }
}

/* Blocks the bins lying wholly within theta of `angle` (fewer bins is always safe). */
static void block_around(g3_ctx *c, double angle)
{
    double lo = (angle - c->theta + G3_PI) / c->width, hi = (angle + c->theta + G3_PI) / c->width;
    long k0 = (long)ceil(lo), k1 = (long)floor(hi) - 1;
    long nb = (long)c->bins;
    for (long k = k0; k <= k1; k++)
        mark_bin(c, (size_t)(((k % nb) + nb) % nb));
}

/* Scans the open Gabriel ball of the edge ring by ring from the midpoint, blocking angles;
 * returns 1 when every angle is blocked (no accepted triangle has ab as a shortest edge), 0
 * otherwise, -1 out of memory. */
static int edge_blocked(g3_ctx *c, const g3_edge *E)
{
    memset(c->mask, 0, c->words * sizeof *c->mask);
    c->blocked = 0;
    double reach2 = 0.25 * E->len2 * (1 - 1e-9), reach = sqrt(reach2);
    for (size_t r = 0;; r++) {
        int beyond = 0;
        c->ring.count = 0;
        if (graph_grid_ring(c->grid, E->m, r, &c->ring, &beyond) < 0) return -1;
        if (beyond) return 0;
        const uint32_t *items = c->ring.data;
        for (size_t i = 0; i < c->ring.count; i++) {
            uint32_t q = items[i];
            if (q == E->a || q == E->b) continue;
            double d2, angle = axis_angle(E, c->xyz + 3 * (size_t)q, &d2);
            if (d2 < reach2 && !isnan(angle)) block_around(c, angle);
        }
        if (c->blocked == c->bins) return 1;
        if ((double)r * c->grid->cell >= reach) return 0;
    }
}

/* Can q be the third vertex of an accepted triangle with shortest edge E? Keeps q whenever a
 * floating comparison is in doubt. */
static int third_vertex_ok(const g3_ctx *c, const g3_edge *E, uint32_t q)
{
    const double *p = c->xyz + 3 * (size_t)q, *pa = c->xyz + 3 * (size_t)E->a,
                 *pb = c->xyz + 3 * (size_t)E->b;
    double da[3] = {p[0] - pa[0], p[1] - pa[1], p[2] - pa[2]};
    double db[3] = {p[0] - pb[0], p[1] - pb[1], p[2] - pb[2]};
    double shortest = E->len2 * (1 - 1e-9);
    if (dot3(da, da) < shortest || dot3(db, db) < shortest) return 0; /* ab is not shortest */
    double d2, angle = axis_angle(E, p, &d2);
    if (isnan(angle)) return 1;
    size_t k = bin_of(c, angle);
    return !(c->mask[k >> 6] >> (k & 63) & 1);
}

static int sort3_check(g3_ctx *c, uint32_t a, uint32_t b, uint32_t q, graph_builder *out)
{
    uint32_t t[3] = {a, b, q}, x;
    if (t[0] > t[1]) x = t[0], t[0] = t[1], t[1] = x;
    if (t[1] > t[2]) x = t[1], t[1] = t[2], t[2] = x;
    if (t[0] > t[1]) x = t[0], t[0] = t[1], t[1] = x;
    return gamma_triangle_check(c->grid, c->params, c->kappa, t, &c->scan, out);
}

/* Every accepted triangle with shortest edge ab goes to the exact check. */
static int edge_triangles(g3_ctx *c, uint32_t a, uint32_t b, graph_builder *out)
{
    g3_edge E;
    if (edge_init(&E, c->xyz, a, b)) {
        int r = edge_blocked(c, &E);
        if (r) return r < 0 ? -1 : 0;
    } else {
        /* No usable frame: no filter, every third vertex is checked. */
        E.a = a;
        E.b = b;
        E.len2 = NAN;
        memset(c->mask, 0, c->words * sizeof *c->mask);
    }
    for (uint32_t q = 0; q < c->n; q++) {
        if (q == a || q == b) continue;
        int keep = isnan(E.len2) ? 1 : third_vertex_ok(c, &E, q);
        if (keep && sort3_check(c, a, b, q, out) < 0) return -1;
    }
    return 0;
}

fl_status gamma3_edge_triangles(const graph_grid *grid, const fl_gamma_params *p, double kappa,
                                const fl_graph_options *opt, graph_builder *b, fl_error *err)
{
    fl_progress_fn progress = opt ? opt->progress : NULL;
    void *user = opt ? opt->progress_user : NULL;
    g3_ctx c;
    memset(&c, 0, sizeof c);
    c.grid = grid;
    c.xyz = grid->coords;
    c.n = grid->n;
    c.params = p;
    c.kappa = kappa;
    double g = 1 / (1 - kappa);
    c.theta = atan(1 / (2 * sqrt(g * g - 1))) * (1 - 1e-6);
    /* theta/2-wide bins, so a blocking point always covers at least its own bin's neighbours;
     * kappa near 1 makes theta tiny and the bins many, capped (wider bins are still safe: a
     * point then blocks only the bins wholly inside its arc, possibly none). */
    double nb = ceil(2 * G3_PI / (0.5 * c.theta));
    c.bins = nb > 4096 || !(nb >= 1) ? 4096 : (size_t)nb;
    c.width = 2 * G3_PI / (double)c.bins;
    c.words = (c.bins + 63) / 64;
    c.mask = calloc(c.words, sizeof *c.mask);
    if (!c.mask) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    fl_vec_init(&c.ring, sizeof(uint32_t));
    fl_vec_init(&c.scan, sizeof(uint32_t));
    fl_status st = FL_OK;
    for (uint32_t i = 0; i < c.n && st == FL_OK; i++) {
        double done = 1 - pow(1 - (double)i / (double)c.n, 2);
        if (fl_progress(progress, user, "gamma triangles", done)) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
            break;
        }
        for (uint32_t j = i + 1; j < c.n; j++)
            if (edge_triangles(&c, i, j, b) < 0) {
                st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
                break;
            }
    }
    fl_vec_free(&c.ring);
    fl_vec_free(&c.scan);
    free(c.mask);
    return st;
}

/* Certifying far cell pairs of the 3D shortest-edge search (docs/gamma.md, "Construction", 3D,
 * "Certifying far cell pairs", Lemma C; thesis ch. 3, Lemma 3.2).
 *
 * The per-pair search of gamma3_edges.c drops a long pair ab after a few points near its
 * midpoint m: with l = |ab|/2, a point q with f_q = (|q-m|^2 - l^2) / (2 r_q) <= F l lies in the
 * lens N_γ(-κ,-κ) of every triangle abc (ab shortest) whose third vertex is within the azimuth
 * theta(F) <= atan(1/s) of q around ab. Lemma C makes that uniform over a cell pair A x B:
 * every pair's midpoint lies in the box (A + B)/2 (centre m0, radius rho), its direction within
 * alpha = asin((rA + rB)/D) of the centres' direction e0, and l >= l_min = gap(A, B)/2. Then
 * |q - m| <= |q - m0| + rho, and the component of q - m normal to the pair moves by at most
 * eps = rho + sin(alpha) |q - m0| from that of q - m0 normal to e0 (radius r0), so its azimuth
 * moves by at most asin(eps / r0); a bound F for every pair follows from l >= l_min. The
 * azimuths normal to each pair are within alpha of the circle normal to e0, sampled by
 * G3C_DIRS test directions: when every test direction lies within
 * theta(F) - asin(eps / r0) - alpha - step/2 of some q, no pair of A x B is the shortest edge of
 * an accepted triangle and the whole cell pair is skipped. Everything not certified goes
 * through the unchanged per-pair scan and the exact check, so the output is the brute force's
 * bit for bit.
 *
 * The pairs are enumerated by a dual-tree recursion over a kd-tree of the points (boxes split
 * at the median of their longest side): well-separated node pairs try the certificate, the
 * others (and failed ones) split the larger node; leaf pairs go to the per-pair callback. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "graphs/gamma3_search.h"

#define G3C_PI 3.14159265358979323846
#define G3C_DIRS 128          /* test directions on the great circle normal to e0 */
#define G3C_LEAF 8            /* points per kd-tree leaf */
#define G3C_SEPARATION 0.2    /* try the certificate when rA + rB <= this * D */
#define G3C_MIN_PAIRS 16      /* smaller cell pairs go straight to the per-pair scan */
#define G3C_MAX_VISITS 200    /* a certificate gives up after this many points */
#define G3C_ANGLE_MARGIN 1e-6 /* radians, against the rounding of the angles */

static double dot3(const double *x, const double *y)
{
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

void gamma3_frame(const double *e, double *u1, double *u2)
{
    /* u1: e crossed with the axis of e's smallest component, u2 = e x u1. */
    int s = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(e[k]) < fabs(e[s])) s = k;
    double axis[3] = {0, 0, 0};
    axis[s] = 1;
    u1[0] = e[1] * axis[2] - e[2] * axis[1];
    u1[1] = e[2] * axis[0] - e[0] * axis[2];
    u1[2] = e[0] * axis[1] - e[1] * axis[0];
    double l1 = sqrt(dot3(u1, u1));
    for (int k = 0; k < 3; k++)
        u1[k] /= l1;
    u2[0] = e[1] * u1[2] - e[2] * u1[1];
    u2[1] = e[2] * u1[0] - e[0] * u1[2];
    u2[2] = e[0] * u1[1] - e[1] * u1[0];
}

/* ---- the certificate (Lemma C) ---- */

typedef struct g3c_cover {
    unsigned char hit[G3C_DIRS];
    int left;
} g3c_cover;

/* Marks the test directions theta_j = (j + 1/2) step - pi with |theta_j - theta| < w
 * (circularly); w < pi/2. */
static void cover_arc(g3c_cover *c, double theta, double w)
{
    const double step = 2 * G3C_PI / G3C_DIRS;
    double lo = floor((theta - w + G3C_PI) / step - 0.5), hi = ceil((theta + w + G3C_PI) / step);
    if (!(lo >= -2 * G3C_DIRS && hi <= 3 * G3C_DIRS)) return; /* NaN or absurd: no cover */
    for (long j = (long)lo; j <= (long)hi; j++) {
        long jj = ((j % G3C_DIRS) + G3C_DIRS) % G3C_DIRS;
        double tj = ((double)jj + 0.5) * step - G3C_PI;
        if (c->hit[jj] || !(fabs(remainder(theta - tj, 2 * G3C_PI)) < w)) continue;
        c->hit[jj] = 1;
        c->left--;
    }
}

/* The geometry of a cell pair shared by its certificate's points. */
typedef struct g3c_pair {
    double m0[3], e0[3], u1[3], u2[3];
    double rho;    /* radius of the midpoint box around m0 */
    double l_min;  /* the smallest half-length of a pair */
    double beta0;  /* atan(1/s): the widest arc a point can kill */
    double R, omega; /* cos(phi) - 2 s sin(phi) = R cos(phi + omega) */
    double slack;  /* alpha + step/2 + margin */
    double sin_alpha;
} g3c_pair;

/* Sets up the pair; 0 when the certificate cannot hold (too close, too wide, not finite). */
static int pair_init(g3c_pair *P, double s, const double *loA, const double *hiA,
                     const double *loB, const double *hiB, double uncertainty)
{
    double cA[3], cB[3], hA[3], hB[3], d[3], gap2 = 0;
    for (int k = 0; k < 3; k++) {
        cA[k] = 0.5 * (loA[k] + hiA[k]);
        cB[k] = 0.5 * (loB[k] + hiB[k]);
        hA[k] = 0.5 * (hiA[k] - loA[k]);
        hB[k] = 0.5 * (hiB[k] - loB[k]);
        d[k] = cB[k] - cA[k];
        P->m0[k] = 0.5 * (cA[k] + cB[k]);
        double g = fmax(loB[k] - hiA[k], loA[k] - hiB[k]);
        if (g > 0) gap2 += g * g;
    }
    /* Rounding: the radii are taken 1e-9 larger, D and l_min 1e-9 smaller (relative). */
    double rAB = (sqrt(dot3(hA, hA)) + sqrt(dot3(hB, hB))) * (1 + 1e-9) * uncertainty;
    double D = sqrt(dot3(d, d)), l_min = 0.5 * sqrt(gap2) * (1 - 1e-9);
    if (!(D > 0) || !isfinite(D) || !isfinite(rAB) || !(l_min > 0)) return 0;
    double sin_alpha = rAB / (D * (1 - 1e-9));
    if (!(sin_alpha < 0.5)) return 0;
    P->sin_alpha = sin_alpha;
    P->slack = asin(sin_alpha) + G3C_PI / G3C_DIRS + G3C_ANGLE_MARGIN;
    P->beta0 = atan(1 / s);
    P->R = sqrt(1 + 4 * s * s);
    P->omega = atan(2 * s);
    P->rho = 0.5 * rAB;
    P->l_min = l_min;
    if (!(P->beta0 > P->slack) || !(P->rho < l_min)) return 0;
    for (int k = 0; k < 3; k++)
        P->e0[k] = d[k] / D;
    gamma3_frame(P->e0, P->u1, P->u2);
    return 1;
}

/* The azimuth around a pair within which q kills every third vertex when f_q / l <= F
 * (Lemma C): cos(phi) - 2 s sin(phi) > sqrt(3) F, capped at atan(1/s); 0 when none. */
static double kill_angle(const g3c_pair *P, double F)
{
    double c = sqrt(3.0) * F / P->R;
    if (!(c < 1)) return 0;
    double theta = c <= -1 ? P->beta0 : acos(c) - P->omega;
    return fmin(theta, P->beta0);
}

/* Adds the test directions point q kills for every pair of the cell pair. */
static void cover_point(g3c_cover *c, const g3c_pair *P, const double *q)
{
    double v[3] = {q[0] - P->m0[0], q[1] - P->m0[1], q[2] - P->m0[2]};
    double d0 = sqrt(dot3(v, v)), x1 = dot3(v, P->u1), x2 = dot3(v, P->u2);
    double r0 = sqrt(x1 * x1 + x2 * x2);
    double d = (d0 + P->rho) * (1 + 1e-9); /* |q - m| for every pair */
    if (!(d < P->l_min)) return;
    /* The component of q - m normal to e moves by at most eps from (x1, x2): rho from the
     * midpoint, sin(alpha) d0 from the direction. */
    double eps = (P->rho + P->sin_alpha * d0) * (1 + 1e-9);
    if (!(r0 > eps)) return;
    double F = (d * d - P->l_min * P->l_min) / (2 * (r0 + eps) * P->l_min); /* >= f_q / l */
    double w = kill_angle(P, F) - asin(eps / r0) - P->slack;
    if (!(w > 0)) return;
    cover_arc(c, atan2(x2, x1), w);
}

int gamma3_cell_certify(const graph_grid *grid, double s, const double *loA, const double *hiA,
                        const double *loB, const double *hiB, double uncertainty, size_t *visits)
{
    g3c_pair P;
    if (!pair_init(&P, s, loA, hiA, loB, hiB, uncertainty)) return 0;
    g3c_cover c;
    memset(c.hit, 0, sizeof c.hit);
    c.left = G3C_DIRS;
    fl_vec ring;
    fl_vec_init(&ring, sizeof(uint32_t));
    size_t seen = 0;
    int ok = 0;
    for (size_t r = 0; !ok && seen < G3C_MAX_VISITS; r++) {
        int beyond = 0;
        ring.count = 0;
        if (graph_grid_ring(grid, P.m0, r, &ring, &beyond) < 0 || beyond) break;
        const uint32_t *items = ring.data;
        for (size_t i = 0; i < ring.count && c.left > 0 && seen < G3C_MAX_VISITS; i++, seen++)
            cover_point(&c, &P, grid->coords + 3 * (size_t)items[i]);
        ok = c.left == 0;
        /* Rings 0..r hold every point closer than r * cell: nothing useful is left. */
        if ((double)r * grid->cell > P.l_min) break;
    }
    fl_vec_free(&ring);
    if (visits) *visits += seen;
    return ok;
}

/* ---- the kd-tree and the dual-tree recursion ---- */

typedef gamma3_kd_node g3c_node;

typedef struct g3c_tree {
    const graph_grid *grid;
    double s;
    gamma3_kdtree kd;
    gamma3_pair_fn fn;
    void *ctx;
    gamma3_stats *stats;
} g3c_tree;

static double coord(const gamma3_kdtree *t, uint32_t i, int axis)
{
    return t->xyz[3 * (size_t)i + (size_t)axis];
}

/* Quickselect: perm[begin..end-1] partitioned around position k along axis. */
static void select_k(gamma3_kdtree *t, uint32_t begin, uint32_t end, uint32_t k, int axis)
{
    uint32_t *p = t->perm;
    while (end - begin > 1) {
        double pivot = coord(t, p[begin + (end - begin) / 2], axis);
        uint32_t i = begin, j = end - 1;
        while (i <= j) {
            while (coord(t, p[i], axis) < pivot) i++;
            while (coord(t, p[j], axis) > pivot) j--;
            if (i <= j) {
                uint32_t x = p[i];
                p[i] = p[j];
                p[j] = x;
                i++;
                if (j == 0) break;
                j--;
            }
        }
        if (k <= j) end = j + 1;
        else if (k >= i) begin = i;
        else return;
    }
}

/* Builds the subtree of node id over perm[begin..end-1]. The points are finite (checked by
 * graph_check_points), so the comparisons above are total. */
static void build(gamma3_kdtree *t, size_t id, uint32_t begin, uint32_t end)
{
    gamma3_kd_node *nd = &t->nodes[id];
    nd->begin = begin;
    nd->end = end;
    nd->child = 0;
    for (int k = 0; k < 3; k++) {
        nd->lo[k] = INFINITY;
        nd->hi[k] = -INFINITY;
    }
    for (uint32_t i = begin; i < end; i++)
        for (int k = 0; k < 3; k++) {
            double x = coord(t, t->perm[i], k);
            nd->lo[k] = fmin(nd->lo[k], x);
            nd->hi[k] = fmax(nd->hi[k], x);
        }
    double h2 = 0;
    int axis = 0;
    for (int k = 0; k < 3; k++) {
        double w = nd->hi[k] - nd->lo[k];
        h2 += 0.25 * w * w;
        if (w > nd->hi[axis] - nd->lo[axis]) axis = k;
    }
    nd->r = sqrt(h2);
    if (end - begin <= G3C_LEAF) return;
    uint32_t mid = begin + (end - begin) / 2;
    select_k(t, begin, end, mid, axis);
    size_t c = t->count;
    t->count += 2;
    t->nodes[id].child = (uint32_t)c;
    build(t, c, begin, mid);
    build(t, c + 1, mid, end);
}

int gamma3_kdtree_build(gamma3_kdtree *t, const double *xyz, size_t n)
{
    memset(t, 0, sizeof *t);
    t->xyz = xyz;
    if (n == 0 || n > UINT32_MAX) return n ? -1 : 0;
    /* A median split gives at most 2 n / (G3C_LEAF / 2) + 1 nodes. */
    size_t cap = 2 * (n / (G3C_LEAF / 2) + 1) + 1;
    t->perm = fl_alloc_array(n, sizeof *t->perm);
    t->nodes = fl_alloc_array(cap, sizeof *t->nodes);
    if (!t->perm || !t->nodes) {
        gamma3_kdtree_free(t);
        return -1;
    }
    for (size_t i = 0; i < n; i++)
        t->perm[i] = (uint32_t)i;
    t->count = 1;
    build(t, 0, 0, (uint32_t)n);
    return 0;
}

void gamma3_kdtree_free(gamma3_kdtree *t)
{
    free(t->perm);
    free(t->nodes);
    t->perm = NULL;
    t->nodes = NULL;
    t->count = 0;
}

static int leaf_pairs(g3c_tree *t, const g3c_node *A, const g3c_node *B)
{
    for (uint32_t i = A->begin; i < A->end; i++)
        for (uint32_t j = A == B ? i + 1 : B->begin; j < B->end; j++) {
            t->stats->pairs_scanned++;
            int r = t->fn(t->ctx, t->kd.perm[i], t->kd.perm[j]);
            if (r < 0) return r;
        }
    return 0;
}

static int try_certificate(g3c_tree *t, const g3c_node *A, const g3c_node *B)
{
    size_t pairs = (size_t)(A->end - A->begin) * (B->end - B->begin);
    if (pairs < G3C_MIN_PAIRS) return 0;
    double d2 = 0;
    for (int k = 0; k < 3; k++) {
        double d = 0.5 * (B->lo[k] + B->hi[k] - A->lo[k] - A->hi[k]);
        d2 += d * d;
    }
    double rab = A->r + B->r;
    if (!(rab * rab <= G3C_SEPARATION * G3C_SEPARATION * d2)) return 0; /* not well separated */
    t->stats->cert_tries++;
    if (!gamma3_cell_certify(t->grid, t->s, A->lo, A->hi, B->lo, B->hi, 1.0,
                             &t->stats->cert_visits))
        return 0;
    t->stats->cert_ok++;
    t->stats->pairs_certified += pairs;
    return 1;
}

/* Every pair of A x B (A != B) or of A (A == B), through the certificate where it holds. */
static int visit(g3c_tree *t, size_t a, size_t b)
{
    const g3c_node *A = &t->kd.nodes[a], *B = &t->kd.nodes[b];
    if (a == b) {
        if (!A->child) return leaf_pairs(t, A, A);
        size_t c = A->child;
        int r = visit(t, c, c);
        if (!r) r = visit(t, c, c + 1);
        if (!r) r = visit(t, c + 1, c + 1);
        return r;
    }
    if (try_certificate(t, A, B)) return 0;
    if (!A->child && !B->child) return leaf_pairs(t, A, B);
    int split_a = B->child == 0 || (A->child != 0 && A->r >= B->r);
    size_t c = split_a ? A->child : B->child;
    int r = split_a ? visit(t, c, b) : visit(t, a, c);
    if (!r) r = split_a ? visit(t, c + 1, b) : visit(t, a, c + 1);
    return r;
}

fl_status gamma3_cell_pairs(const graph_grid *grid, double s, gamma3_pair_fn fn, void *ctx,
                            gamma3_stats *stats, fl_error *err)
{
    g3c_tree t;
    memset(&t, 0, sizeof t);
    gamma3_stats local;
    memset(&local, 0, sizeof local);
    t.grid = grid;
    t.s = s;
    t.fn = fn;
    t.ctx = ctx;
    t.stats = stats ? stats : &local;
    if (grid->n < 2) return FL_OK;
    if (gamma3_kdtree_build(&t.kd, grid->coords, grid->n) < 0)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    int r = visit(&t, 0, 0);
    gamma3_kdtree_free(&t.kd);
    if (r == -1) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    if (r < 0) return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
    return FL_OK;
}

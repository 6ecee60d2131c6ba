/* Candidate generation for the non-Delaunay triangles (c1' < 0) of a 3D γ-graph from their
 * shortest edge (docs/gamma.md, "Construction", 3D; thesis ch. 3, Lemma 3.2).
 *
 * Let abc be accepted (c1' >= -kappa, kappa < 1) and non-Delaunay. Its symmetric lens
 * Λ = B(C - Tn) ∩ B(C + Tn) is empty (Lemma 3.2; C, R circumcentre and circumradius, n the unit
 * normal, s = sqrt(g^2-1), g = 1/(1-kappa), T = sR, both balls of radius gR through the
 * circumcircle). Take ab a shortest edge: length L = 2l, midpoint m, and cylindrical
 * coordinates around the line ab (axial x, radius r, angle theta). The angle at c is at most
 * 60°, so C lies on c's side of ab: at height h >= l/sqrt(3) above m in the half-plane of c,
 * with h = (|c-m|^2 - l^2) / (2 r_c) and R^2 = h^2 + l^2.
 *
 * Lens test (the proof is in docs/gamma.md): a point q lies in the open Λ iff
 *     f_q := (|q-m|^2 - l^2) / (2 r_q)  <  h cos(phi) - s sqrt(h^2 + l^2) |sin(phi)|,
 * phi the angle between q and c around ab. The right side increases with h when
 * |phi| < atan(1/s) (30° for kappa = 0.5), so q blocks every third vertex of its angle range
 * whose h exceeds a threshold h*(f_q, phi), and no other. Per angle bin the smallest threshold
 * H[j] over the points seen bounds the admissible h: the edge is dead when every H[j] is below
 * l/sqrt(3), and the third vertices have h_c <= H[bin(c)], hence |c-m| <= H + sqrt(H^2 + l^2):
 * the ring scan around m stops there, and the points it saw are the only candidates.
 *
 * The filters are floating and keep a candidate whenever in doubt (worst angle of a bin,
 * relative slack, ill-conditioned angles ignored); each candidate is then decided by
 * gamma_triangle_check, the exact early-decided witness scan, so the output and its (c0', c1')
 * are the brute force's. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "graphs/gamma3_search.h"

#define G3_PI 3.14159265358979323846
#define G3_BINS_PER_ARC 8 /* bins per blocking half-arc atan(1/s) */
#define G3_MAX_REACH 8
#define G3_KD_AFTER 1       /* scan_edge goes from rings to the kd-tree after this ring */
#define G3_QUICK_ERR 1e-5   /* bound on the error of gamma3_quick_angle (radians), see there */
#define G3_WIT_MAX 24       /* witnesses kept for one dropped pair */
#define G3_MAX_BINS 4096

typedef struct g3_ctx {
    const graph_grid *grid;
    const double *xyz;
    size_t n;
    const fl_gamma_params *params;
    double kappa;
    double s;         /* sqrt(g^2 - 1) */
    size_t bins;      /* angle bins around an edge */
    double width;     /* 2 pi / bins */
    int reach;        /* bins a point can block on each side of its own */
    double ca[G3_MAX_REACH + 1], cb[G3_MAX_REACH + 1]; /* cos, s sin of the worst angle */
    double inv_c[G3_MAX_REACH + 1];                    /* 1 / (ca^2 - cb^2) */
    double kill[G3_MAX_REACH + 1]; /* f/l below which a point's threshold is under l/sqrt(3) */
    int quick_reach;  /* the same for the quick drop test, whose angles err by G3_QUICK_ERR */
    int quick_full;   /* the last quick_point call killed its whole reach */
    uint64_t qdead[G3_MAX_BINS / 64]; /* the bins the quick tests killed (bit k: bin k) */
    double inv_width;                 /* bins / (2 pi) */
    double quick_kill[G3_MAX_REACH + 1];
    int plain;        /* 1: the per-pair scan alone (no quick drop test), for the tests */
    int witness;      /* 1: witness reuse (docs/gamma.md, "Round 11: witness reuse") */
    uint32_t *killer; /* per bin, the point that killed it or set its limit (scan_edge) */
    unsigned char *mark; /* per point, scratch of collect_killers (all 0 between calls) */
    uint32_t wit[G3_WIT_MAX]; /* the points that killed bins of the current pair */
    size_t wit_count;
    uint32_t extra[G3_WIT_MAX]; /* points of the current pair that killed their whole reach */
    size_t extra_count;         /* but no bin still alive */
    uint32_t last[G3_WIT_MAX]; /* the witnesses of the last dropped pair */
    size_t last_count;
    uint32_t *by_b;   /* per point b, G3_WIT_MAX witnesses of the last dropped pair (a', b) */
    unsigned char *by_b_count;
    gamma3_kdtree kd; /* the far part of scan_edge (kd_scan); empty when plain */
    uint32_t *stamp;  /* stamp[q] == pair_stamp: q is already in seen */
    uint32_t pair_stamp;
    fl_vec stack;     /* kd_scan's node stack */
    gamma3_stats *stats;
    double *limit;    /* H[j] of the current edge */
    unsigned char *dead; /* bins whose limit is below l/sqrt(3) (no third vertex there) */
    size_t dead_count;
    double h_min;     /* l/sqrt(3), less a margin, of the current edge (scan_edge) */
    size_t low_count; /* bins dead or with a limit below h_min: all of them drop the edge */
    double max_h;     /* live_max's cached value, valid unless max_dirty */
    int max_dirty;
    fl_vec seen; /* the points of the rings scanned around the current edge's midpoint */
    fl_vec scan; /* scratch of gamma_triangle_check */
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
    gamma3_frame(E->e, E->u1, E->u2);
    return 1;
}

/* The components of p - m normal to the edge, (x1, x2) in the frame (u1, u2); returns 0 when
 * the angle is ill-conditioned (p within 1e-6 |p - m| of the axis, or not finite). *dist2 =
 * |p - m|^2, *radius = the distance from the axis. */
static inline int axis_plane(const g3_edge *E, const double *p, double *x1, double *x2,
                             double *dist2, double *radius)
{
    double d[3] = {p[0] - E->m[0], p[1] - E->m[1], p[2] - E->m[2]};
    *x1 = dot3(d, E->u1);
    *x2 = dot3(d, E->u2);
    *dist2 = dot3(d, d);
    double r2 = *x1 * *x1 + *x2 * *x2;
    *radius = sqrt(r2);
    return r2 > 1e-12 * *dist2 && isfinite(r2);
}

/* The cylindrical coordinates of p around the edge: returns the angle in [-pi, pi] within
 * G3_QUICK_ERR (gamma3_quick_angle; the scan's tables allow that error for both the blocking
 * point and the third vertex), or NAN when it is ill-conditioned (see axis_plane). */
static double axis_coords(const g3_edge *E, const double *p, double *dist2, double *radius)
{
    double x1, x2;
    if (!axis_plane(E, p, &x1, &x2, dist2, radius)) return NAN;
    return gamma3_quick_angle(x1, x2);
}

static size_t bin_of(const g3_ctx *c, double angle)
{
    /* A product instead of a division: near a bin edge the bin may be the neighbour, i.e. the
     * angle is off its bin by rounding (1e-15 rad), far inside the 1e-9 of kill_table. */
    double k = floor((angle + G3_PI) * c->inv_width);
    if (!(k >= 0)) return 0;
    return k >= (double)c->bins ? c->bins - 1 : (size_t)k;
}

/* The smallest h from which q (with f = f_q) blocks third vertices at angle phi from it, phi
 * given by A = cos(phi) > B = s |sin(phi)|: the root of A h - B sqrt(h^2 + l^2) = f. */
static double threshold(double A, double B, double f, double l2)
{
    double C = A * A - B * B;
    return (A * f + B * sqrt(f * f + C * l2)) / C;
}

/* Lowers H[j] with q's thresholds over the bins within reach of q's bin, each taken at the
 * farthest angle a third vertex of that bin can have from q (the threshold grows with |phi|).
 * A bin whose threshold falls below l/sqrt(3) can hold no third vertex at all ("dead"); that
 * is decided first, without the square root: threshold(f) < h_min iff f < g(h_min) =
 * l (A - 2B)/sqrt(3), g increasing (see threshold). */
static void block_point(g3_ctx *c, uint32_t q, double angle, double f, double l, double l2)
{
    long home = (long)bin_of(c, angle), nb = (long)c->bins;
    for (long d = -c->reach; d <= c->reach; d++) {
        long kk = home + d;
        size_t k = (size_t)(kk < 0 ? kk + nb : kk >= nb ? kk - nb : kk);
        if (c->dead[k]) continue;
        int far = d < 0 ? (int)-d : (int)d;
        int low = c->limit[k] < c->h_min;
        if (f < l * c->kill[far]) {
            c->max_dirty = 1;
            c->dead[k] = 1;
            c->dead_count++;
            c->low_count += !low;
            c->killer[k] = q;
            continue;
        }
        /* sqrt(f^2 + C l^2) >= |f|: a bin whose limit is already below that lower bound of
         * the threshold keeps its limit (skipping an update only keeps a larger limit). */
        double A = c->ca[far], B = c->cb[far];
        if ((A * f + B * fabs(f)) * c->inv_c[far] >= c->limit[k]) continue;
        double h = threshold(A, B, f, l2);
        if (h < c->limit[k]) {
            c->limit[k] = h;
            c->max_dirty = 1;
            c->killer[k] = q;
            c->low_count += !low && h < c->h_min;
        }
    }
}

/* h of a third vertex at squared distance d2 from m and distance r from the axis. */
static double apex_height(double d2, double r, double l2)
{
    return (d2 - l2) / (2 * r);
}

/* atan2(y, x) for finite (x, y) != (0, 0), within G3_QUICK_ERR: a minimax polynomial for atan on
 * [0, 1] (error below 1.7e-6 rad, checked densely by tests/graphs/test_gamma3_quick.c) and the
 * octant symmetries. The quick drop test's kill arcs are shortened by G3_QUICK_ERR and the
 * scan's tables by twice that (axis_coords), so the error cannot make either drop a pair or a
 * third vertex the exact angles would keep. */
double gamma3_quick_angle(double x, double y)
{
    double ax = fabs(x), ay = fabs(y), mx = ax > ay ? ax : ay, mn = ax > ay ? ay : ax;
    double a = mn / mx, s = a * a;
    double r = a * (0.99997726 +
                    s * (-0.33262347 +
                         s * (0.19354346 + s * (-0.11643287 + s * (0.05265332 + s * -0.01172120)))));
    if (ay > ax) r = 0.5 * G3_PI - r;
    if (x < 0) r = G3_PI - r;
    return y < 0 ? -r : r;
}

/* The 27 cells of rings 0 and 1: the home cell, then each neighbour followed by the opposite
 * one, so that the azimuths around the edge spread fast. */
static const signed char quick_cells[27][3] = {
    {0, 0, 0},   {1, 0, 0},   {-1, 0, 0},  {0, 1, 0},   {0, -1, 0}, {0, 0, 1},   {0, 0, -1},
    {1, 1, 1},   {-1, -1, -1}, {1, -1, 1}, {-1, 1, -1}, {1, 1, -1}, {-1, -1, 1}, {1, -1, -1},
    {-1, 1, 1},  {1, 1, 0},   {-1, -1, 0}, {1, -1, 0},  {-1, 1, 0}, {1, 0, 1},   {-1, 0, -1},
    {1, 0, -1},  {-1, 0, 1},  {0, 1, 1},   {0, -1, -1}, {0, 1, -1}, {0, -1, 1}};

/* The number of bits set (without a library call on targets lacking the instruction). */
static inline size_t popcount64(uint64_t x)
{
    x = x - ((x >> 1) & 0x5555555555555555u);
    x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fu;
    return (size_t)((x * 0x0101010101010101u) >> 56);
}

/* Marks the bins lo..hi (lo <= hi < bins) dead in c->qdead; returns how many were alive. */
static size_t kill_bins(g3_ctx *c, size_t lo, size_t hi)
{
    size_t killed = 0;
    for (size_t w = lo / 64; w <= hi / 64; w++) {
        size_t from = w == lo / 64 ? lo % 64 : 0, to = w == hi / 64 ? hi % 64 : 63;
        uint64_t bits = (to == 63 ? ~(uint64_t)0 : (((uint64_t)1 << (to + 1)) - 1)) &
                        ~(((uint64_t)1 << from) - 1);
        bits &= ~c->qdead[w];
        killed += popcount64(bits);
        c->qdead[w] |= bits;
    }
    return killed;
}

/* One point of the quick drop test: kills the bins within its kill arc; returns the number of
 * bins still alive. */
static size_t quick_point(g3_ctx *c, const g3_edge *E, uint32_t q, double l, double l2,
                          size_t left)
{
    double x1, x2, d2, rq;
    c->quick_full = 0;
    if (q == E->a || q == E->b || !axis_plane(E, c->xyz + 3 * (size_t)q, &x1, &x2, &d2, &rq))
        return left;
    double f = apex_height(d2, rq, l2);
    if (!(f < l * c->quick_kill[0])) return left; /* kills nothing (or not finite) */
    int reach = 0; /* quick_kill decreases: the bins killed are contiguous */
    while (reach < c->quick_reach && f < l * c->quick_kill[reach + 1])
        reach++;
    c->quick_full = reach == c->quick_reach;
    long nb = (long)c->bins, home = (long)bin_of(c, gamma3_quick_angle(x1, x2));
    long lo = home - reach, hi = home + reach;
    if (lo < 0)
        return left - kill_bins(c, 0, (size_t)hi) - kill_bins(c, (size_t)(lo + nb), (size_t)nb - 1);
    if (hi >= nb)
        return left - kill_bins(c, (size_t)lo, (size_t)nb - 1) - kill_bins(c, 0, (size_t)(hi - nb));
    return left - kill_bins(c, (size_t)lo, (size_t)hi);
}

/* quick_point, and the bookkeeping of witness reuse: a point that kills bins goes to c->wit,
 * one that kills its whole reach but no live bin to c->extra (see witness_test). */
static size_t witness_point(g3_ctx *c, const g3_edge *E, uint32_t q, double l, double l2,
                            size_t left)
{
    size_t now = quick_point(c, E, q, l, l2, left);
    if (now < left) {
        if (c->wit_count < G3_WIT_MAX) c->wit[c->wit_count++] = q;
    } else if (c->quick_full && c->extra_count < G3_WIT_MAX)
        c->extra[c->extra_count++] = q;
    return now;
}

/* The quick drop test (docs/gamma.md, "Quick drop test"): the points of the 27 grid cells
 * around m's cell (rings 0 and 1, read straight from the grid in the order of quick_cells)
 * kill the bins within their kill arc (quick_kill: the arc of block_point shortened by
 * G3_QUICK_ERR). Only the kills are tracked, no limits and no square roots of thresholds.
 * Returns 1 when every bin is killed: then every azimuth around ab lies within the kill arc of
 * some point q (the arc bounds the true angle to q, the error of q's angle included), so q lies
 * in the lens of every triangle abc with ab shortest (the lens test above) and no triangle with
 * shortest edge ab is accepted. 0 when not shown (the pair goes to scan_edge). */
static int quick_drop(g3_ctx *c, const g3_edge *E, size_t left)
{
    const graph_grid *g = c->grid;
    double l2 = 0.25 * E->len2, l = sqrt(l2);
    long home[3], res[3];
    for (int a = 0; a < 3; a++) {
        res[a] = (long)g->res[a];
        double x = floor((E->m[a] - g->lo[a]) / g->cell);
        home[a] = !(x >= 0) ? 0 : x >= (double)res[a] ? res[a] - 1 : (long)x;
    }
    for (int j = 0; j < 27; j++) {
        long x = home[0] + quick_cells[j][0], y = home[1] + quick_cells[j][1],
             z = home[2] + quick_cells[j][2];
        if (x < 0 || y < 0 || z < 0 || x >= res[0] || y >= res[1] || z >= res[2]) continue;
        size_t cell = ((size_t)z * g->res[1] + (size_t)y) * g->res[0] + (size_t)x;
        for (size_t i = g->start[cell]; i < g->start[cell + 1]; i++) {
            if (c->stats) c->stats->quick_visits++;
            uint32_t q = g->items[i];
            left = witness_point(c, E, q, l, l2, left);
            if (left == 0) return 1;
        }
    }
    return 0;
}

/* Witness reuse (docs/gamma.md, "Round 11: witness reuse"). quick_point's kill test holds for
 * any point q, not only for the 27 cells of quick_drop: its proof (see quick_drop) uses only
 * f_q, q's approximate angle and the arc shortened by G3_QUICK_ERR. So the points that killed
 * the bins of an earlier dropped pair are tried first; if they kill every bin of this pair,
 * the pair is dropped by the same proof, else quick_drop goes on from the bins they killed.
 * The witness lists are hints: a wrong or stale list costs time, never a triangle. */

/* Tests, with quick_point on the cleared bins, the witnesses of the last dropped pair (in the
 * kd order usually (a, b') with b' just before b) and those of the last dropped pair (a', b)
 * (a' usually the point before a); the points that kill bins go to c->wit, those that kill
 * their whole reach but no live bin to c->extra. Returns the bins left alive. */
static size_t witness_test(g3_ctx *c, const g3_edge *E)
{
    double l2 = 0.25 * E->len2, l = sqrt(l2);
    size_t left = c->bins;
    const uint32_t *list[2] = {c->last, c->by_b + (size_t)E->b * G3_WIT_MAX};
    size_t count[2] = {c->last_count, c->by_b_count[E->b]};
    for (int t = 0; t < 2; t++)
        for (size_t i = 0; i < count[t]; i++) {
            uint32_t q = list[t][i];
            if (c->stats) c->stats->witness_visits++;
            left = witness_point(c, E, q, l, l2, left);
            if (left == 0) return 0;
        }
    return left;
}

/* The pair (a, b) was dropped: the witnesses c->wit, then c->extra (up to G3_WIT_MAX in all),
 * become the last list and b's list. */
static void remember(g3_ctx *c, uint32_t b)
{
    for (size_t i = 0; i < c->extra_count && c->wit_count < G3_WIT_MAX; i++)
        c->wit[c->wit_count++] = c->extra[i];
    memcpy(c->last, c->wit, c->wit_count * sizeof *c->wit);
    c->last_count = c->wit_count;
    memcpy(c->by_b + (size_t)b * G3_WIT_MAX, c->wit, c->wit_count * sizeof *c->wit);
    c->by_b_count[b] = (unsigned char)c->wit_count;
}

/* After scan_edge dropped the pair: the distinct points that killed a bin or set its limit
 * (every bin is dead or has a limit below l/sqrt(3), set during this pair) go to c->wit. */
static void collect_killers(g3_ctx *c)
{
    c->wit_count = 0;
    c->extra_count = 0;
    for (size_t k = 0; k < c->bins && c->wit_count < G3_WIT_MAX; k++) {
        uint32_t q = c->killer[k];
        if (c->mark[q]) continue;
        c->mark[q] = 1;
        c->wit[c->wit_count++] = q;
    }
    for (size_t i = 0; i < c->wit_count; i++)
        c->mark[c->wit[i]] = 0;
}

/* One point seen by scan_edge: lowers the bin limits; returns 1 when every bin is dead. */
static int see_point(g3_ctx *c, const g3_edge *E, uint32_t q, double l, double l2)
{
    if (q == E->a || q == E->b) return 0;
    double d2, rq, angle = axis_coords(E, c->xyz + 3 * (size_t)q, &d2, &rq);
    if (isnan(angle)) return 0;
    double f = apex_height(d2, rq, l2);
    if (isfinite(f)) block_point(c, q, angle, f, l, l2);
    return c->dead_count == c->bins;
}

/* The largest limit over the live bins (INFINITY when one is NaN, -INFINITY when every bin is
 * dead), recomputed only after block_point changed a bin. */
static double live_max(g3_ctx *c)
{
    if (c->max_dirty) {
        double h = -INFINITY;
        for (size_t k = 0; k < c->bins; k++)
            if (!c->dead[k]) h = isnan(c->limit[k]) ? INFINITY : fmax(h, c->limit[k]);
        c->max_h = h;
        c->max_dirty = 0;
    }
    return c->max_h;
}

/* Can a point of the box [lo, hi] still be an admissible third vertex of E? (docs/gamma.md,
 * "The far part of the scan".) An admissible c has |c-m| >= sqrt(3) l (ab is shortest) and
 * h_c >= g(|c-m|), g(d) = (d^2 - l^2) / (2d) increasing, so every c of the box has
 * h_c >= G = g(max(box distance, sqrt(3) l)); c is blocked when h_c exceeds the limit of its
 * bin. The box's bins are those of the azimuth range of its points (centre angle +- asin(r/rho)
 * from the box's circumscribed ball), or all bins when the box comes near the axis (where
 * third_vertex_ok keeps points without an angle). Keeps the box whenever in doubt. */
static int box_needed(g3_ctx *c, const g3_edge *E, const gamma3_kd_node *nd, double l, double l2)
{
    double v[3], dist2 = 0;
    for (int k = 0; k < 3; k++) {
        double below = nd->lo[k] - E->m[k], above = E->m[k] - nd->hi[k];
        double gap = below > 0 ? below : above > 0 ? above : 0; /* finite: no fmax call */
        dist2 += gap * gap;
        v[k] = 0.5 * (nd->lo[k] + nd->hi[k]) - E->m[k];
    }
    double d = fmax(sqrt(dist2), sqrt(3.0) * l * (1 - 1e-9)) * (1 - 1e-7);
    double G = (d * d - l2) / (2 * d);
    if (!(G > 0)) return 1;
    double x1 = dot3(v, E->u1), x2 = dot3(v, E->u2), rho = sqrt(x1 * x1 + x2 * x2);
    double delta = nd->r * (1 + 1e-12), vlen = sqrt(dot3(v, v));
    long nb = (long)c->bins, k0 = 0, k1 = nb - 1;
    if (rho - delta > 1e-5 * (vlen + delta)) {
        double theta = atan2(x2, x1), hw = asin(delta / rho) + 1e-7;
        k0 = (long)floor((theta - hw + G3_PI) / c->width) - 1;
        k1 = (long)floor((theta + hw + G3_PI) / c->width) + 1;
        if (!(k0 >= -nb && k1 <= 2 * nb && k1 - k0 < nb)) k0 = 0, k1 = nb - 1;
    }
    /* The test below at the largest live limit, first: H + 1e-9 (|H| + l) increases with H. */
    double top = live_max(c);
    if (top == -INFINITY || G > top + 1e-9 * (fabs(top) + l)) return 0;
    if (k0 == 0 && k1 == nb - 1) return 1;
    for (long kk = k0; kk <= k1; kk++) {
        size_t k = (size_t)(kk < 0 ? kk + nb : kk >= nb ? kk - nb : kk);
        double H = c->limit[k];
        if (!c->dead[k] && !(G > H + 1e-9 * (fabs(H) + l))) return 1;
    }
    return 0;
}

/* The far part of scan_edge: after the rings 0..r_done (every point closer to m than
 * r_done * cell is in seen, stamped), the kd-tree is walked nearest child first, skipping the
 * boxes that box_needed proves to hold no admissible third vertex under the current limits
 * (which only decrease). Returns 1 when the edge is dead, 0 when the points seen hold every
 * admissible third vertex, -1 out of memory. */
static int kd_scan(g3_ctx *c, const g3_edge *E, size_t r_done, double l, double l2)
{
    const uint32_t *items = c->seen.data;
    for (size_t i = 0; i < c->seen.count; i++)
        c->stamp[items[i]] = c->pair_stamp;
    double inner = (double)r_done * c->grid->cell * (1 - 1e-9);
    const gamma3_kd_node *nodes = c->kd.nodes;
    c->stack.count = 0;
    uint32_t root = 0;
    if (fl_vec_push(&c->stack, &root, 1)) return -1;
    while (c->stack.count) {
        uint32_t id = ((uint32_t *)c->stack.data)[--c->stack.count];
        const gamma3_kd_node *nd = &nodes[id];
        double far2 = 0; /* the box's farthest distance from m: inside the rings when small */
        for (int k = 0; k < 3; k++) {
            double wl = fabs(nd->lo[k] - E->m[k]), wh = fabs(nd->hi[k] - E->m[k]);
            double w = wl > wh ? wl : wh;
            far2 += w * w;
        }
        if (sqrt(far2) < inner || !box_needed(c, E, nd, l, l2)) continue;
        if (nd->child) {
            /* Push the farther child first, so that the nearer one is walked first. */
            uint32_t ch[2] = {nd->child, nd->child + 1};
            double dc[2];
            for (int j = 0; j < 2; j++) {
                const gamma3_kd_node *x = &nodes[ch[j]];
                double v[3] = {0.5 * (x->lo[0] + x->hi[0]) - E->m[0],
                               0.5 * (x->lo[1] + x->hi[1]) - E->m[1],
                               0.5 * (x->lo[2] + x->hi[2]) - E->m[2]};
                dc[j] = dot3(v, v);
            }
            uint32_t order[2] = {dc[0] > dc[1] ? ch[0] : ch[1], dc[0] > dc[1] ? ch[1] : ch[0]};
            if (fl_vec_push(&c->stack, order, 2)) return -1;
            continue;
        }
        for (uint32_t i = nd->begin; i < nd->end; i++) {
            uint32_t q = c->kd.perm[i];
            if (c->stamp[q] == c->pair_stamp) continue;
            c->stamp[q] = c->pair_stamp;
            if (fl_vec_push(&c->seen, &q, 1)) return -1;
            if (see_point(c, E, q, l, l2)) return 1;
        }
        if (c->low_count == c->bins) return 1; /* live_max(c) < h_min */
    }
    return 0;
}

/* Scans rings around m, lowering the bin limits, until the edge is dead (returns 1) or every
 * admissible third vertex has been seen (returns 0; the points are in c->seen); -1 out of
 * memory. Beyond ring G3_KD_AFTER the kd-tree walk kd_scan takes over (not when plain). */
static int scan_edge(g3_ctx *c, const g3_edge *E)
{
    double l2 = 0.25 * E->len2, l = sqrt(l2);
    double h_min = l / sqrt(3.0) * (1 - 1e-7);
    for (size_t k = 0; k < c->bins; k++)
        c->limit[k] = INFINITY;
    memset(c->dead, 0, c->bins);
    c->dead_count = 0;
    c->h_min = h_min;
    c->low_count = 0;
    c->max_dirty = 1;
    c->seen.count = 0;
    for (size_t r = 0;; r++) {
        int beyond = 0;
        size_t first = c->seen.count;
        if (graph_grid_ring(c->grid, E->m, r, &c->seen, &beyond) < 0) return -1;
        if (beyond) return 0;
        const uint32_t *items = c->seen.data;
        for (size_t i = first; i < c->seen.count; i++)
            if (see_point(c, E, items[i], l, l2)) return 1; /* typically within the first ring */
        double H = live_max(c);
        if (H < h_min) return 1;
        double need = H + sqrt(H * H + l2);
        if ((double)r * c->grid->cell >= need * (1 + 1e-7)) return 0;
        if (!c->plain && r >= G3_KD_AFTER) {
            if (++c->pair_stamp == 0) { /* wrapped: no stale stamp may match */
                memset(c->stamp, 0, c->n * sizeof *c->stamp);
                c->pair_stamp = 1;
            }
            if (c->stats) c->stats->kd_walks++;
            return kd_scan(c, E, r, l, l2);
        }
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
    double d2, rq, angle = axis_coords(E, p, &d2, &rq);
    if (isnan(angle)) return 1;
    size_t k = bin_of(c, angle);
    if (c->dead[k]) return 0;
    double l2 = 0.25 * E->len2, h = apex_height(d2, rq, l2), H = c->limit[k];
    return !(h > H + 1e-7 * (fabs(h) + fabs(H) + sqrt(l2)));
}

static int sort3_check(g3_ctx *c, uint32_t a, uint32_t b, uint32_t q, graph_builder *out)
{
    uint32_t t[3] = {a, b, q}, x;
    if (t[0] > t[1]) x = t[0], t[0] = t[1], t[1] = x;
    if (t[1] > t[2]) x = t[1], t[1] = t[2], t[2] = x;
    if (t[0] > t[1]) x = t[0], t[0] = t[1], t[1] = x;
    /* The kd-tree exists unless plain (the round-9 path, kept as the tests' reference). */
    if (c->kd.nodes) return gamma_triangle_check_kd(&c->kd, c->params, c->kappa, t, &c->scan, out);
    return gamma_triangle_check(c->grid, c->params, c->kappa, t, &c->scan, out);
}

/* Every accepted triangle with shortest edge ab goes to the exact check. */
static int edge_triangles(g3_ctx *c, uint32_t a, uint32_t b, graph_builder *out)
{
    g3_edge E;
    if (!edge_init(&E, c->xyz, a, b)) {
        /* No usable frame: no filter, every third vertex is checked. */
        for (uint32_t q = 0; q < c->n; q++)
            if (q != a && q != b && sort3_check(c, a, b, q, out) < 0) return -1;
        return 0;
    }
    if (!c->plain) {
        size_t left = c->bins;
        memset(c->qdead, 0, ((c->bins + 63) / 64) * sizeof *c->qdead);
        c->wit_count = 0;
        c->extra_count = 0;
        if (c->witness) {
            left = witness_test(c, &E);
            if (left == 0) {
                if (c->stats) c->stats->witness_dropped++;
                remember(c, b);
                return 0;
            }
        }
        if (quick_drop(c, &E, left)) {
            if (c->stats) c->stats->quick_dropped++;
            if (c->witness) remember(c, b);
            return 0;
        }
    }
    int r = scan_edge(c, &E);
    if (r < 0) return -1;
    if (c->stats) {
        if (r) c->stats->scan_dropped++;
        else c->stats->scan_kept++;
        c->stats->scan_visits += c->seen.count;
    }
    if (r) {
        if (c->witness) {
            collect_killers(c);
            remember(c, b);
        }
        return 0;
    }
    const uint32_t *items = c->seen.data;
    for (size_t i = 0; i < c->seen.count; i++) {
        uint32_t q = items[i];
        if (q == a || q == b || !third_vertex_ok(c, &E, q)) continue;
        if (c->stats) c->stats->candidates++;
        if (sort3_check(c, a, b, q, out) < 0) return -1;
    }
    return 0;
}

/* The per-pair callback of gamma3_cell_pairs, with the progress report. */
typedef struct g3_run {
    g3_ctx *c;
    graph_builder *out;
    fl_progress_fn progress;
    void *user;
    size_t done, total;
} g3_run;

static int run_pair(void *user, uint32_t a, uint32_t b)
{
    g3_run *run = user;
    if ((++run->done & 0xffff) == 0 &&
        fl_progress(run->progress, run->user, "gamma triangles",
                    fmin(1.0, (double)run->done / (double)run->total)))
        return -2;
    return edge_triangles(run->c, a, b, run->out);
}

/* For a point in bin i and a third vertex in bin i + d (|d| <= reach, the return value), the
 * angle between them is at most (d+1) widths, plus `err` for an inexact angle of the point:
 * kill[d] is f/l below which the point's threshold there is under l/sqrt(3) (with a margin for
 * the rounding of f, relative 1e-8 of l), ca[d], cb[d] (when not NULL) the cos and s sin of
 * that angle. The table stops where a vertex of the bin can be beyond the arc atan(1/s). */
static int kill_table(const g3_ctx *c, double err, double *ca, double *cb, double *kill)
{
    int reach = 0;
    for (int d = 0; d <= G3_MAX_REACH; d++) {
        double phi = (d + 1) * c->width + err + 1e-9, A = cos(phi), B = c->s * sin(phi);
        if (ca) ca[d] = A;
        if (cb) cb[d] = B;
        double k = (A - 2 * B) / sqrt(3.0);
        kill[d] = k - 1e-7 * fabs(k) - 1e-8;
        /* A vertex of the bin can be at an angle beyond the arc: no blocking there. */
        if (!(phi < G3_PI / 2 && A > B * (1 + 1e-9))) break;
        reach = d;
    }
    return reach;
}

/* Frees what gamma3_edge_triangles_with allocated (any part may still be NULL or empty). */
static void ctx_free(g3_ctx *c)
{
    fl_vec_free(&c->seen);
    fl_vec_free(&c->scan);
    fl_vec_free(&c->stack);
    gamma3_kdtree_free(&c->kd);
    free(c->stamp);
    free(c->limit);
    free(c->dead);
    free(c->killer);
    free(c->mark);
    free(c->by_b);
    free(c->by_b_count);
}

fl_status gamma3_edge_triangles(const graph_grid *grid, const fl_gamma_params *p, double kappa,
                                const fl_graph_options *opt, graph_builder *b, fl_error *err)
{
    return gamma3_edge_triangles_with(grid, p, kappa, opt, GAMMA3_DEFAULT_PAIRS, b, NULL, err);
}

fl_status gamma3_edge_triangles_with(const graph_grid *grid, const fl_gamma_params *p,
                                     double kappa, const fl_graph_options *opt,
                                     gamma3_pairs pairs, graph_builder *b, gamma3_stats *stats,
                                     fl_error *err)
{
    fl_progress_fn progress = opt ? opt->progress : NULL;
    void *user = opt ? opt->progress_user : NULL;
    g3_ctx c;
    memset(&c, 0, sizeof c);
    fl_vec_init(&c.seen, sizeof(uint32_t));
    fl_vec_init(&c.scan, sizeof(uint32_t));
    fl_vec_init(&c.stack, sizeof(uint32_t));
    c.grid = grid;
    c.xyz = grid->coords;
    c.n = grid->n;
    c.params = p;
    c.kappa = kappa;
    double g = 1 / (1 - kappa);
    c.s = sqrt(g * g - 1);
    /* Bins of width atan(1/s)/8: a point reaches 7 bins each side; a vertex of a bin d away
     * is at most (d+1) widths from it. Few bins for kappa near 0 (s near 0, wide arcs). */
    double arc = atan(1 / c.s), nb = ceil(2 * G3_PI / (arc / G3_BINS_PER_ARC));
    c.bins = nb > G3_MAX_BINS || !(nb >= 1) ? G3_MAX_BINS : nb < 8 ? 8 : (size_t)nb;
    c.width = 2 * G3_PI / (double)c.bins;
    c.inv_width = (double)c.bins / (2 * G3_PI);
    /* The scan's angles (axis_coords) err by G3_QUICK_ERR for q and for the third vertex. */
    c.reach = kill_table(&c, 2 * G3_QUICK_ERR, c.ca, c.cb, c.kill);
    for (int d = 0; d <= c.reach; d++)
        c.inv_c[d] = 1 / (c.ca[d] * c.ca[d] - c.cb[d] * c.cb[d]);
    c.quick_reach = kill_table(&c, G3_QUICK_ERR, NULL, NULL, c.quick_kill);
    c.plain = (pairs & GAMMA3_PLAIN_SCAN) != 0;
    c.witness = !c.plain && !(pairs & GAMMA3_NO_WITNESS) && c.n > 1;
    c.stats = stats;
    c.limit = fl_alloc_array(c.bins, sizeof *c.limit);
    c.dead = calloc(c.bins, 1);
    c.killer = calloc(c.bins, sizeof *c.killer);
    if (c.witness) {
        c.mark = calloc(c.n, 1);
        c.by_b = fl_alloc_array(c.n, G3_WIT_MAX * sizeof *c.by_b);
        c.by_b_count = calloc(c.n, 1);
    }
    if (!c.limit || !c.dead || !c.killer ||
        (c.witness && (!c.mark || !c.by_b || !c.by_b_count))) {
        ctx_free(&c);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    if (!c.plain && c.n > 1) {
        c.stamp = calloc(c.n, sizeof *c.stamp);
        if (!c.stamp || gamma3_kdtree_build(&c.kd, c.xyz, c.n) < 0) {
            ctx_free(&c);
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
        }
    }
    /* With witness reuse the pairs go in the kd-tree's order of the points (leaves of nearby
     * points in a row), so that consecutive pairs have nearby midpoints and the witnesses of
     * one dropped pair are likely to drop the next: pair (order[i], order[j]) for i < j is
     * every unordered pair once, as in index order; the builder sorts the output. */
    const uint32_t *order = c.witness ? c.kd.perm : NULL;
    fl_status st = FL_OK;
    if (pairs & GAMMA3_CELL_PAIRS) {
        g3_run run = {&c, b, progress, user, 0, c.n * (c.n - 1) / 2};
        st = gamma3_cell_pairs(grid, c.s, run_pair, &run, stats, err);
    } else {
        for (uint32_t i = 0; i < c.n && st == FL_OK; i++) {
            double done = 1 - pow(1 - (double)i / (double)c.n, 2);
            if (fl_progress(progress, user, "gamma triangles", done)) {
                st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
                break;
            }
            uint32_t a = order ? order[i] : i;
            for (uint32_t j = i + 1; j < c.n; j++)
                if (edge_triangles(&c, a, order ? order[j] : j, b) < 0) {
                    st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
                    break;
                }
            if (stats) stats->pairs_scanned += c.n - 1 - i;
        }
    }
    ctx_free(&c);
    return st;
}

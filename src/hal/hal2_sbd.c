/* Smallest enclosing disc of a ring's vertices (thesis §7.2.2: the root of a flintstone tree)
 * by Welzl's randomized incremental algorithm, expected O(n) time. The decisions "is p outside
 * the current circle" are exact: fl_incircle for a circle through three points and
 * fl_diametral for a circle with diameter ab. */
#include <math.h>

#include "core/core.h"
#include "hal/hal2_internal.h"

/* ---- Welzl's algorithm (move-to-front free, three nested loops) ---- */

typedef struct circle {
    const double *s[3]; /* support points */
    int n;              /* 1, 2 or 3 */
} circle;

/* 1 when p is strictly outside the circle c, decided exactly. */
static int circle_excludes(const circle *c, const double *p)
{
    if (c->n == 1) return p[0] != c->s[0][0] || p[1] != c->s[0][1];
    if (c->n == 2) return fl_diametral(c->s[0], c->s[1], p, 2) > 0;
    int o = fl_orient2d(c->s[0], c->s[1], c->s[2]);
    return fl_incircle(c->s[0], c->s[1], c->s[2], p) * o < 0;
}

/* The circle through a, b, c where the three points are on the boundary of the smallest disc
 * holding them. Collinear triples (impossible in exact Welzl, kept for safety with repeated
 * points) get the diametral circle of their farthest pair. */
static circle circle3(const double *a, const double *b, const double *c)
{
    circle r = {{a, b, c}, 3};
    if (fl_orient2d(a, b, c) != 0) return r;
    if (fl_diametral(a, b, c, 2) <= 0) return (circle){{a, b, NULL}, 2};
    if (fl_diametral(a, c, b, 2) <= 0) return (circle){{a, c, NULL}, 2};
    return (circle){{b, c, NULL}, 2};
}

static void shuffle(uint32_t *idx, size_t n)
{
    uint64_t state = 0x9E3779B97F4A7C15ULL ^ n; /* deterministic: same input, same tree */
    for (size_t k = n; k > 1; k--) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        size_t r = (size_t)((state >> 33) % k);
        uint32_t t = idx[k - 1];
        idx[k - 1] = idx[r];
        idx[r] = t;
    }
}

static circle welzl(const double *xy, const uint32_t *idx, size_t n)
{
#define PT(k) (xy + 2 * (size_t)idx[k])
    circle c = {{PT(0), NULL, NULL}, 1};
    for (size_t i = 1; i < n; i++) {
        if (!circle_excludes(&c, PT(i))) continue;
        c = (circle){{PT(i), NULL, NULL}, 1};
        for (size_t j = 0; j < i; j++) {
            if (!circle_excludes(&c, PT(j))) continue;
            c = (circle){{PT(i), PT(j), NULL}, 2};
            for (size_t k = 0; k < j; k++)
                if (circle_excludes(&c, PT(k))) c = circle3(PT(i), PT(j), PT(k));
        }
    }
#undef PT
    return c;
}

/* 1 when p is exactly on the circle c. */
static int circle_on(const circle *c, const double *p)
{
    if (c->n == 2) return fl_diametral(c->s[0], c->s[1], p, 2) == 0;
    return fl_incircle(c->s[0], c->s[1], c->s[2], p) == 0;
}

/* Floating distance; hypot, not the squared distance, which underflows to 0 for coordinates
 * near 1e-300 and made every vertex tie with `from` itself (the root pair was one vertex
 * twice, so one edge was covered twice and reported twice by fl_hal2_intersect). */
static double dist(const double *a, const double *b)
{
    return hypot(a[0] - b[0], a[1] - b[1]);
}

/* Of the vertices on the circle, the one farthest from `from` (floating distances), never one
 * at the same point as `from`: a circle through three points exactly (c->n == 3) holds at least
 * two distinct points, so the root pair always spans a chord. */
static uint32_t farthest_on_circle(const double *xy, const uint32_t *idx, size_t n, const circle *c,
                                   uint32_t from)
{
    const double *f = xy + 2 * (size_t)from;
    uint32_t best = from;
    double bd = -1;
    for (size_t k = 0; k < n; k++) {
        const double *p = xy + 2 * (size_t)idx[k];
        if (p[0] == f[0] && p[1] == f[1]) continue;
        double d = dist(p, f);
        if (d > bd && circle_on(c, p)) bd = d, best = idx[k];
    }
    return best;
}

static uint32_t index_of(const double *xy, const uint32_t *idx, size_t n, const double *p)
{
    for (size_t k = 0; k < n; k++)
        if (xy + 2 * (size_t)idx[k] == p) return idx[k];
    return idx[0];
}

void fl_hal2_sbd(const double *xy, uint32_t *idx, size_t n, uint32_t *i, uint32_t *j,
                 double disc[3])
{
    shuffle(idx, n);
    circle c = welzl(xy, idx, n);
    if (c.n == 1) { /* all vertices coincide */
        *i = idx[0];
        *j = idx[n > 1 ? 1 : 0];
    } else {
        /* "If more than two vertices lie on the boundary of the smallest bounding disc, we take
         * two vertices that are farthest apart" (§7.2.2): two farthest-point sweeps over the
         * cocircular vertices; for a diametral circle the support pair already is a diameter. */
        uint32_t a = index_of(xy, idx, n, c.s[0]);
        if (c.n == 2) {
            *i = a;
            *j = index_of(xy, idx, n, c.s[1]);
        } else {
            uint32_t b = farthest_on_circle(xy, idx, n, &c, a);
            *i = farthest_on_circle(xy, idx, n, &c, b);
            *j = b;
        }
    }
    /* The stored disc: centre of the chosen pair's circle is not needed exactly; any centre
     * works once r2 is the largest computed distance (see FL_HAL2_REL). */
    double cx = 0, cy = 0;
    if (c.n == 3) {
        const double *a = c.s[0], *b = c.s[1], *d = c.s[2];
        double bx = b[0] - a[0], by = b[1] - a[1], dx = d[0] - a[0], dy = d[1] - a[1];
        double den = 2 * (bx * dy - by * dx), b2 = bx * bx + by * by, d2 = dx * dx + dy * dy;
        cx = a[0] + (dy * b2 - by * d2) / den;
        cy = a[1] + (bx * d2 - dx * b2) / den;
    } else {
        const double *a = c.s[0], *b = c.n == 2 ? c.s[1] : c.s[0];
        cx = a[0] + (b[0] - a[0]) / 2;
        cy = a[1] + (b[1] - a[1]) / 2;
    }
    disc[0] = cx;
    disc[1] = cy;
    disc[2] = 0;
    for (size_t k = 0; k < n; k++) {
        double d = fl_hal2_d2(disc, xy[2 * (size_t)idx[k]], xy[2 * (size_t)idx[k] + 1]);
        if (d > disc[2]) disc[2] = d;
    }
}

/* Independent references for the graph tests: Definition 3.1 evaluated literally (two balls,
 * every point tested for membership), exact predicates in GMP rationals, and graph helpers.
 * Nothing here calls the library's γ code. */
#ifndef GAMMA_ORACLE_H
#define GAMMA_ORACLE_H

#include <gmp.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"

/* ---- exact signs in rationals (doubles convert exactly) ---- */

static inline int oracle_orient2(const double *a, const double *b, const double *c)
{
    mpq_t t[6], l, r;
    const double v[6] = {a[0], a[1], b[0], b[1], c[0], c[1]};
    for (int i = 0; i < 6; i++) {
        mpq_init(t[i]);
        mpq_set_d(t[i], v[i]);
    }
    mpq_init(l);
    mpq_init(r);
    mpq_sub(t[0], t[0], t[4]); /* a - c */
    mpq_sub(t[1], t[1], t[5]);
    mpq_sub(t[2], t[2], t[4]); /* b - c */
    mpq_sub(t[3], t[3], t[5]);
    mpq_mul(l, t[0], t[3]);
    mpq_mul(r, t[1], t[2]);
    int s = mpq_cmp(l, r);
    for (int i = 0; i < 6; i++)
        mpq_clear(t[i]);
    mpq_clear(l);
    mpq_clear(r);
    return (s > 0) - (s < 0);
}

/* Sign of the determinant of an n x n matrix (n <= 5) of doubles, exactly (fraction-free
 * elimination in rationals). */
static inline int oracle_det_sign(int n, const double *m)
{
    mpq_t a[25], f, t;
    for (int i = 0; i < n * n; i++) {
        mpq_init(a[i]);
        mpq_set_d(a[i], m[i]);
    }
    mpq_init(f);
    mpq_init(t);
    int sign = 1;
    for (int c = 0; c < n && sign; c++) {
        int p = c;
        while (p < n && mpq_sgn(a[p * n + c]) == 0)
            p++;
        if (p == n) {
            sign = 0;
            break;
        }
        if (p != c) {
            for (int j = 0; j < n; j++)
                mpq_swap(a[p * n + j], a[c * n + j]);
            sign = -sign;
        }
        if (mpq_sgn(a[c * n + c]) < 0) sign = -sign;
        for (int r = c + 1; r < n; r++) {
            mpq_div(f, a[r * n + c], a[c * n + c]);
            for (int j = c; j < n; j++) {
                mpq_mul(t, f, a[c * n + j]);
                mpq_sub(a[r * n + j], a[r * n + j], t);
            }
        }
    }
    for (int i = 0; i < n * n; i++)
        mpq_clear(a[i]);
    mpq_clear(f);
    mpq_clear(t);
    return sign;
}

/* Rational |p|^2 and dot products need more than doubles: lift through a rational matrix. */
static inline int oracle_lifted_det_sign(int n, int dim, const double *const *pts)
{
    /* rows: (p_i, |p_i|^2, 1), i < n; n = dim + 2 */
    mpq_t a[25], f, t, x;
    mpq_init(f);
    mpq_init(t);
    mpq_init(x);
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++)
            mpq_init(a[i * n + j]);
        mpq_set_ui(a[i * n + dim], 0, 1);
        for (int j = 0; j < dim; j++) {
            mpq_set_d(a[i * n + j], pts[i][j]);
            mpq_mul(x, a[i * n + j], a[i * n + j]);
            mpq_add(a[i * n + dim], a[i * n + dim], x);
        }
        mpq_set_ui(a[i * n + dim + 1], 1, 1);
    }
    int sign = 1;
    for (int c = 0; c < n && sign; c++) {
        int p = c;
        while (p < n && mpq_sgn(a[p * n + c]) == 0)
            p++;
        if (p == n) {
            sign = 0;
            break;
        }
        if (p != c) {
            for (int j = 0; j < n; j++)
                mpq_swap(a[p * n + j], a[c * n + j]);
            sign = -sign;
        }
        if (mpq_sgn(a[c * n + c]) < 0) sign = -sign;
        for (int r = c + 1; r < n; r++) {
            mpq_div(f, a[r * n + c], a[c * n + c]);
            for (int j = c; j < n; j++) {
                mpq_mul(t, f, a[c * n + j]);
                mpq_sub(a[r * n + j], a[r * n + j], t);
            }
        }
    }
    for (int i = 0; i < n * n; i++)
        mpq_clear(a[i]);
    mpq_clear(f);
    mpq_clear(t);
    mpq_clear(x);
    return sign;
}

/* orient3 > 0 iff d is on the side (b-a)x(c-a) points to. */
static inline int oracle_side3(const double *a, const double *b, const double *c, const double *d)
{
    double m[16];
    const double *p[4] = {a, b, c, d};
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 3; j++)
            m[i * 4 + j] = p[i][j];
        m[i * 4 + 3] = 1;
    }
    /* det[a 1; b 1; c 1; d 1] = -det[b-a; c-a; d-a] */
    return -oracle_det_sign(4, m);
}

/* +1 iff e is strictly inside the circle (2D, pts a,b,c) / sphere (3D, a,b,c,d). */
static inline int oracle_in_ball(int dim, const double *const *pts, const double *e)
{
    const double *rows[5];
    for (int i = 0; i <= dim; i++)
        rows[i] = pts[i];
    rows[dim + 1] = e;
    int lifted = oracle_lifted_det_sign(dim + 2, dim, rows);
    int orient = dim == 2 ? oracle_orient2(pts[0], pts[1], pts[2])
                          : oracle_side3(pts[0], pts[1], pts[2], pts[3]);
    /* det[p, |p|^2, 1] over (simplex, e) is positive for e inside a counter-clockwise
     * triangle, and negative inside a tetrahedron positive in oracle_side3's convention
     * (checked on the unit simplex in test_oracle_in_ball_signs). */
    return dim == 2 ? lifted * orient : -lifted * orient;
}

/* Sign of (p-a).(p-b): < 0 iff p is strictly inside the ball with diameter ab. */
static inline int oracle_diametral(int dim, const double *a, const double *b, const double *p)
{
    mpq_t s, x, y, t;
    mpq_init(s);
    mpq_init(x);
    mpq_init(y);
    mpq_init(t);
    for (int i = 0; i < dim; i++) {
        mpq_set_d(x, p[i]);
        mpq_set_d(t, a[i]);
        mpq_sub(x, x, t);
        mpq_set_d(y, p[i]);
        mpq_set_d(t, b[i]);
        mpq_sub(y, y, t);
        mpq_mul(t, x, y);
        mpq_add(s, s, t);
    }
    int r = mpq_sgn(s);
    mpq_clear(s);
    mpq_clear(x);
    mpq_clear(y);
    mpq_clear(t);
    return r;
}

/* ---- Definition 3.1 literally, in long double ---- */

typedef struct oracle_frame {
    int dim;
    long double c[3], n[3], r;
    const double *v[3];
} oracle_frame;

static inline int oracle_frame_init(oracle_frame *f, const double *pts, int dim, const uint32_t *s)
{
    f->dim = dim;
    for (int i = 0; i < dim; i++)
        f->v[i] = pts + (size_t)s[i] * dim;
    long double a[3] = {0}, b[3] = {0}, c[3] = {0};
    for (int i = 0; i < dim; i++) {
        a[i] = f->v[0][i];
        b[i] = f->v[1][i] - a[i];
        if (dim == 3) c[i] = f->v[2][i] - a[i];
    }
    if (dim == 2) {
        long double len = sqrtl(b[0] * b[0] + b[1] * b[1]);
        if (len == 0) return 0;
        f->c[0] = a[0] + b[0] / 2;
        f->c[1] = a[1] + b[1] / 2;
        f->r = len / 2;
        f->n[0] = -b[1] / len;
        f->n[1] = b[0] / len;
        return 1;
    }
    /* Solve for the circumcentre x = a + s b + t c with |x-a| = |x-v1| = |x-v2|. */
    long double bb = 0, cc = 0, bc = 0;
    for (int i = 0; i < 3; i++) {
        bb += b[i] * b[i];
        cc += c[i] * c[i];
        bc += b[i] * c[i];
    }
    long double det = bb * cc - bc * bc;
    if (det <= 0) return 0;
    long double s1 = (cc * bb - bc * cc) / (2 * det), t1 = (bb * cc - bc * bb) / (2 * det);
    long double n[3] = {b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2],
                        b[0] * c[1] - b[1] * c[0]};
    long double nl = sqrtl(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), r2 = 0;
    for (int i = 0; i < 3; i++) {
        long double rel = s1 * b[i] + t1 * c[i];
        f->c[i] = a[i] + rel;
        f->n[i] = n[i] / nl;
        r2 += rel * rel;
    }
    f->r = sqrtl(r2);
    return 1;
}

/* Is p in the open ball with centre offset t (t = +-INFINITY: open half-space)? */
static inline int oracle_in_ball_t(const oracle_frame *f, const double *p, long double t)
{
    long double h = 0, d2 = 0;
    for (int i = 0; i < f->dim; i++) {
        long double d = p[i] - f->c[i];
        h += d * f->n[i];
        d2 += d * d;
    }
    if (isinf(t)) return t > 0 ? h > 0 : h < 0;
    /* |p - C - t n|^2 < r^2 + t^2  <=>  |p-C|^2 - r^2 < 2 t h */
    return d2 - f->r * f->r < 2 * t * h;
}

static inline long double oracle_offset(long double c, long double r)
{
    long double a = fabsl(c);
    if (a >= 1) return INFINITY;
    long double k = 1 / (1 - a);
    return r * sqrtl(k * k - 1);
}

/* Is N_γ(c0,c1) of simplex s empty in either mirror position? Random inputs only: points on the
 * simplex's hyperplane are not handled here (they do not occur in general position). */
static inline int oracle_gamma_empty(const double *pts, size_t n, int dim, const uint32_t *s,
                                     double c0, double c1)
{
    oracle_frame f;
    if (!oracle_frame_init(&f, pts, dim, s)) return 0;
    for (int side = -1; side <= 1; side += 2) {
        long double t1 = side * oracle_offset(c1, f.r), t0;
        if (c0 == 0 || c1 == 0)
            t0 = 0;
        else
            t0 = (c0 * c1 > 0 ? -side : side) * oracle_offset(c0, f.r);
        int empty = 1;
        for (size_t i = 0; i < n && empty; i++) {
            int vertex = 0;
            for (int k = 0; k < dim; k++)
                vertex |= s[k] == i;
            if (vertex) continue;
            const double *p = pts + i * dim;
            int in0 = oracle_in_ball_t(&f, p, t0), in1 = oracle_in_ball_t(&f, p, t1);
            if (c1 >= 0 ? (in0 || in1) : (in0 && in1)) empty = 0;
        }
        if (empty) return 1;
    }
    return 0;
}

/* ---- point sets and graph helpers ---- */

static inline double *oracle_random_points(size_t n, int dim, unsigned long long seed)
{
    double *p = malloc(n * dim * sizeof *p);
    for (size_t i = 0; i < n * dim; i++)
        p[i] = fl_test_rand01(&seed);
    return p;
}

/* Integer lattice points in a box (many cocircular, collinear and coplanar subsets), shuffled. */
static inline double *oracle_grid_points(size_t n, int dim, int side, unsigned long long seed)
{
    double *p = malloc(n * dim * sizeof *p);
    size_t total = 1;
    for (int i = 0; i < dim; i++)
        total *= side;
    char *used = calloc(total, 1);
    for (size_t i = 0; i < n; i++) {
        size_t code;
        do
            code = fl_test_rand_u64(&seed) % total;
        while (used[code]);
        used[code] = 1;
        for (int j = 0; j < dim; j++) {
            p[i * dim + j] = (double)(code % side);
            code /= side;
        }
    }
    free(used);
    return p;
}

/* Is simplex s (sorted) in the graph? Simplices are sorted lexicographically. */
static inline int oracle_graph_has(const fl_graph *g, const uint32_t *s)
{
    size_t lo = 0, hi = g->simplex_count;
    int k = g->simplex_size;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        int c = 0;
        for (int i = 0; i < k && !c; i++)
            if (g->simplices[mid * k + i] != s[i]) c = g->simplices[mid * k + i] < s[i] ? -1 : 1;
        if (c == 0) return 1;
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return 0;
}

/* Is every simplex of a also in b? */
static inline int oracle_graph_subset(const fl_graph *a, const fl_graph *b)
{
    for (size_t i = 0; i < a->simplex_count; i++)
        if (!oracle_graph_has(b, a->simplices + i * a->simplex_size)) return 0;
    return 1;
}

static inline int oracle_graph_equal(const fl_graph *a, const fl_graph *b)
{
    return a->simplex_count == b->simplex_count && oracle_graph_subset(a, b);
}

#endif /* GAMMA_ORACLE_H */

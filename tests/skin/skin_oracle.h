/* Independent oracles for the skin tests; they share no code with src/skin.
 *
 * skin_oracle_value: the skin function straight from its definition (Cheng & Tan §6.1),
 * G(x) = min over lambda in the simplex of pi(x, (sum lambda_i b_i)^t), where the combination is
 * taken in lifted coordinates (z, |z|^2 - w) (§2.1). The minimand
 *     h(lambda) = |x - Z lambda|^2 - t |Z lambda|^2 + t c.lambda,  c_i = |z_i|^2 - w_i,
 * is convex; its minimiser over the simplex is the minimiser over the affine hull of its support,
 * a set of at most 4 balls. So G is the minimum, over every subset S of <= 4 balls whose
 * affine-hull minimiser (KKT system, long double) has nonnegative coefficients, of h there.
 *
 * euler_union_oracle: the Euler characteristic of the union of balls from its dual (alpha)
 * complex at alpha = 0 (Edelsbrunner): a simplex X of the regular triangulation belongs to it iff
 * some point of its power cell nu_X lies inside the balls of X. The power of such points is
 * |p - f|^2 + w_X on aff(nu_X) (f the focus, w_X the orthogonal weight), so the smallest value
 * over nu_X is w_X when f lies in nu_X (tested against every ball), and otherwise the smallest
 * value over the boundary of nu_X, i.e. over the cofaces. */
#ifndef SKIN_ORACLE_H
#define SKIN_ORACLE_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "flintstone.h"

typedef long double ld;

/* Solves the m x m system a x = b (row-major, destroyed) by Gaussian elimination with partial
 * pivoting; -1 when singular relative to its largest entry. */
static int oracle_solve(int m, ld *a, ld *b, ld *x)
{
    ld big = 0;
    for (int i = 0; i < m * m; i++)
        if (fabsl(a[i]) > big) big = fabsl(a[i]);
    for (int c = 0; c < m; c++) {
        int p = c;
        for (int r = c + 1; r < m; r++)
            if (fabsl(a[r * m + c]) > fabsl(a[p * m + c])) p = r;
        if (!(fabsl(a[p * m + c]) > 1e-13L * big)) return -1;
        for (int j = 0; j < m; j++) {
            ld tmp = a[c * m + j];
            a[c * m + j] = a[p * m + j];
            a[p * m + j] = tmp;
        }
        ld tmp = b[c];
        b[c] = b[p];
        b[p] = tmp;
        for (int r = c + 1; r < m; r++) {
            ld f = a[r * m + c] / a[c * m + c];
            for (int j = c; j < m; j++)
                a[r * m + j] -= f * a[c * m + j];
            b[r] -= f * b[c];
        }
    }
    for (int r = m - 1; r >= 0; r--) {
        ld s = b[r];
        for (int j = r + 1; j < m; j++)
            s -= a[r * m + j] * x[j];
        x[r] = s / a[r * m + r];
    }
    return 0;
}

/* min of h over the affine hull of the balls idx[0..m-1] if its minimiser is a convex
 * combination, else HUGE_VALL. KKT: 2(1-t) Z^T Z lambda + mu 1 = 2 Z^T x - t c, sum lambda = 1. */
static ld oracle_subset(const double *xyzw, const int *idx, int m, double t, const double *x)
{
    ld a[25], b[5], sol[5];
    int n = m + 1;
    for (int i = 0; i < m; i++) {
        const double *zi = xyzw + 4 * idx[i];
        ld zx = 0, zz = 0;
        for (int k = 0; k < 3; k++) {
            zx += (ld)zi[k] * x[k];
            zz += (ld)zi[k] * zi[k];
        }
        for (int j = 0; j < m; j++) {
            const double *zj = xyzw + 4 * idx[j];
            ld d = 0;
            for (int k = 0; k < 3; k++)
                d += (ld)zi[k] * zj[k];
            a[i * n + j] = 2 * (1 - (ld)t) * d;
        }
        a[i * n + m] = 1;
        a[m * n + i] = 1;
        b[i] = 2 * zx - (ld)t * (zz - zi[3]);
    }
    a[m * n + m] = 0;
    b[m] = 1;
    if (oracle_solve(n, a, b, sol)) return HUGE_VALL;
    ld z[3] = {0, 0, 0}, lc = 0;
    for (int i = 0; i < m; i++) {
        if (sol[i] < -1e-12L) return HUGE_VALL;
        const double *zi = xyzw + 4 * idx[i];
        for (int k = 0; k < 3; k++)
            z[k] += sol[i] * zi[k];
        lc += sol[i] * ((ld)zi[0] * zi[0] + (ld)zi[1] * zi[1] + (ld)zi[2] * zi[2] - zi[3]);
    }
    ld d2 = 0, z2 = 0;
    for (int k = 0; k < 3; k++) {
        d2 += (x[k] - z[k]) * (x[k] - z[k]);
        z2 += z[k] * z[k];
    }
    return d2 - (ld)t * z2 + (ld)t * lc;
}

static ld skin_oracle_value(const double *xyzw, int n, double t, const double *x)
{
    ld best = HUGE_VALL;
    int idx[4];
    for (int a = 0; a < n; a++) {
        idx[0] = a;
        ld v = oracle_subset(xyzw, idx, 1, t, x);
        if (v < best) best = v;
        for (int b = a + 1; b < n; b++) {
            idx[1] = b;
            v = oracle_subset(xyzw, idx, 2, t, x);
            if (v < best) best = v;
            for (int c = b + 1; c < n; c++) {
                idx[2] = c;
                v = oracle_subset(xyzw, idx, 3, t, x);
                if (v < best) best = v;
                for (int d = c + 1; d < n; d++) {
                    idx[3] = d;
                    v = oracle_subset(xyzw, idx, 4, t, x);
                    if (v < best) best = v;
                }
            }
        }
    }
    return best;
}

/* |G(v)| / |grad G(v)| from the oracle (central differences with step d). */
static double skin_oracle_offset(const double *xyzw, int n, double t, const double *v, double d)
{
    ld g2 = 0;
    for (int c = 0; c < 3; c++) {
        double a[3] = {v[0], v[1], v[2]}, b[3] = {v[0], v[1], v[2]};
        a[c] += d;
        b[c] -= d;
        ld gc = (skin_oracle_value(xyzw, n, t, a) - skin_oracle_value(xyzw, n, t, b)) / (2 * d);
        g2 += gc * gc;
    }
    return (double)(fabsl(skin_oracle_value(xyzw, n, t, v)) / sqrtl(g2));
}

/* ---- Euler characteristic of the union of balls through the alpha complex ---- */

typedef struct oracle_simplex {
    uint32_t v[4]; /* sorted, UINT32_MAX padded */
    int k;
    ld alpha;
} oracle_simplex;

static int oracle_cmp(const void *pa, const void *pb)
{
    const oracle_simplex *a = pa, *b = pb;
    for (int i = 0; i < 4; i++)
        if (a->v[i] != b->v[i]) return a->v[i] < b->v[i] ? -1 : 1;
    return 0;
}

/* Focus-and-weight of the balls v[0..k]: f in their affine hull with equal power w to all. */
static int oracle_focus(const double *xyzw, const uint32_t *v, int k, ld f[3], ld *w)
{
    /* f = z0 + sum eta_j e_j, 2 e_i . (f - z0) = |e_i|^2 - w_i + w_0 */
    ld a[9], b[3], eta[3] = {0, 0, 0}, e[3][3];
    const double *z0 = xyzw + 4 * v[0];
    for (int i = 0; i < k; i++)
        for (int c = 0; c < 3; c++)
            e[i][c] = (ld)xyzw[4 * v[i + 1] + c] - z0[c];
    for (int i = 0; i < k; i++) {
        for (int j = 0; j < k; j++)
            a[i * k + j] = 2 * (e[i][0] * e[j][0] + e[i][1] * e[j][1] + e[i][2] * e[j][2]);
        b[i] = a[i * k + i] / 2 - xyzw[4 * v[i + 1] + 3] + z0[3];
    }
    if (k > 0 && oracle_solve(k, a, b, eta)) return -1;
    ld d2 = 0;
    for (int c = 0; c < 3; c++) {
        f[c] = z0[c];
        for (int j = 0; j < k; j++)
            f[c] += eta[j] * e[j][c];
        d2 += (f[c] - z0[c]) * (f[c] - z0[c]);
    }
    *w = d2 - z0[3];
    return 0;
}

/* Every simplex (vertex, edge, triangle, tetrahedron) of the regular triangulation of the n
 * balls, sorted by oracle_cmp without repeats, in a calloc'ed array of *count; NULL when the
 * triangulation cannot be built or memory runs out. */
static oracle_simplex *oracle_rt_simplices(const double *xyzw, size_t n, size_t *count)
{
    fl_rt3 rt;
    fl_error err;
    *count = 0;
    if (fl_rt3_build(xyzw, n, NULL, &rt, &err) != FL_OK) return NULL;
    size_t m = rt.tet_count * 15, u = 0;
    oracle_simplex *s = calloc(m ? m : 1, sizeof *s);
    if (!s) {
        fl_rt3_free(&rt);
        return NULL;
    }
    for (size_t t = 0; t < rt.tet_count; t++)
        for (uint32_t mask = 1; mask < 16; mask++) {
            oracle_simplex *x = &s[u++];
            int k = 0;
            for (int i = 0; i < 4; i++)
                if (mask >> i & 1) x->v[k++] = rt.tet[4 * t + i];
            for (int i = 1; i < k; i++)
                for (int j = i; j > 0 && x->v[j - 1] > x->v[j]; j--) {
                    uint32_t tmp = x->v[j];
                    x->v[j] = x->v[j - 1];
                    x->v[j - 1] = tmp;
                }
            x->k = k - 1;
            for (int i = k; i < 4; i++)
                x->v[i] = UINT32_MAX;
        }
    fl_rt3_free(&rt);
    qsort(s, m, sizeof *s, oracle_cmp);
    u = 0;
    for (size_t i = 0; i < m; i++)
        if (u == 0 || oracle_cmp(&s[i], &s[u - 1])) s[u++] = s[i];
    *count = u;
    return s;
}

/* Euler characteristic of the union of the n balls (n >= 4 centres in general position);
 * sets *ok = 0 when the regular triangulation cannot be built. */
static long long euler_union_oracle(const double *xyzw, size_t n, int *ok)
{
    size_t u;
    *ok = 0;
    oracle_simplex *s = oracle_rt_simplices(xyzw, n, &u);
    if (!s) return 0;
    /* from tetrahedra down to vertices: cofaces are decided before their faces */
    long long chi = 0;
    for (int k = 3; k >= 0; k--)
        for (size_t i = 0; i < u; i++) {
            if (s[i].k != k) continue;
            ld f[3] = {0, 0, 0}, w = 0; /* set by oracle_focus (initialised for gcc -O2) */
            oracle_focus(xyzw, s[i].v, k, f, &w);
            int inside_cell = 1;
            for (size_t j = 0; j < n && inside_cell; j++) {
                int member = 0;
                for (int a = 0; a <= k; a++)
                    member |= s[i].v[a] == j;
                if (member) continue;
                ld p = -xyzw[4 * j + 3];
                for (int c = 0; c < 3; c++)
                    p += (f[c] - xyzw[4 * j + c]) * (f[c] - xyzw[4 * j + c]);
                if (p < w) inside_cell = 0;
            }
            ld alpha = w;
            if (!inside_cell) {
                alpha = HUGE_VALL;
                for (size_t j = 0; j < u; j++) { /* immediate cofaces */
                    if (s[j].k != k + 1) continue;
                    int contains = 1;
                    for (int a = 0; a <= k && contains; a++) {
                        int hit = 0;
                        for (int b = 0; b <= k + 1; b++)
                            hit |= s[j].v[b] == s[i].v[a];
                        contains = hit;
                    }
                    if (contains && s[j].alpha < alpha) alpha = s[j].alpha;
                }
            }
            s[i].alpha = alpha;
            if (alpha < 0) chi += (k % 2 == 0) ? 1 : -1;
        }
    free(s);
    *ok = 1;
    return chi;
}

#endif

/* The Euler characteristic of a union of balls (fl_balls_union_euler), so that a skin mesh can
 * be checked against it: body^t(B) is homotopy equivalent to the union of the balls
 * (Edelsbrunner, "Deformable smooth surface design", 1999; Cheng & Tan Theorem 15), hence the
 * skin, the boundary of a compact 3-manifold, has Euler characteristic 2 chi(union B).
 *
 * The union is homotopy equivalent to its dual complex K (the alpha complex at alpha = 0; nerve
 * theorem on the balls restricted to their power cells): a simplex X of the regular
 * triangulation is in K iff some point of its power cell nu_X lies inside the (open) balls of
 * X, i.e. has negative power pi_X to them. On aff(nu_X) the power is |p - f|^2 + pi_X(f), with
 * f the focus of X (the point of aff X with equal power to its balls), so:
 *   - if f lies in nu_X, X is in K iff pi_X(f) < 0;
 *   - else the minimum of the power over the convex set nu_X lies on its boundary, the union of
 *     the cells nu_Y of X's immediate cofaces Y, where pi_X = pi_Y; X is in K iff one of its
 *     cofaces is. (And whenever a coface is in K, X is, since nu_Y is in nu_X.)
 * nu_X is the part of aff(nu_X) where pi_b >= pi_X for the balls b of X's link (the facets of
 * nu_X are the cells of the cofaces X + b), so "f in nu_X" is one local test per coface. A
 * hull simplex has an unbounded cell; its facets are still the cells of its cofaces in the
 * triangulation (the unbounded directions have no coface), so the same rule holds with the
 * link taken over the tetrahedra that exist. A tetrahedron's cell is the point f itself.
 * Simplices are decided from tetrahedra down to vertices.
 *
 * Exactness. Both decisions are signs of polynomials in the input doubles. With a = z_0,
 * e_i = z_i - a (i < k), G_ij = e_i.e_j (det G > 0 for the simplex of a triangulation),
 * s_i = |e_i|^2 - w_i + w_0 (so f = a + sum eta_i e_i with G eta = s / 2):
 *   - link test of ball b: pi_b(f) - pi_X(f) = s_b - g^T G^-1 s with g_i = e_i.e_b, and by
 *     the Schur complement det [[G, g], [s^T, s_b]] = det G (s_b - s^T G^-1 g): same sign;
 *   - power: pi_X(f) = |f - a|^2 - w_0 = s^T G^-1 s / 4 - w_0, and
 *     det [[G, s], [s^T, 4 w_0]] = det G (4 w_0 - s^T G^-1 s): the opposite sign.
 * Each determinant (at most 4 x 4) is first evaluated in floating point with a forward error
 * bound (bordered_filter); when the value is not certified it is evaluated in big integers
 * (bordered_exact: the inputs scaled by one power of two into integers, src/predicates'
 * fl_big). Ties (f on a facet of nu_X) are harmless either way: there f is also the focus of
 * the coface and pi_X(f) its value, so both branches give the same answer.
 *
 * Fewer than 4 distinct centres, or all centres in a plane, have no 3D regular triangulation.
 * Then four auxiliary balls of large negative weight are added around the set (a regular
 * tetrahedron of exactly representable centres far outside it): their power is positive
 * everywhere, so they add no point to the union and no simplex to K, but they make the
 * triangulation exist. Duplicate and hidden balls are not vertices; they lie inside the union of
 * the others, so K is unchanged by them. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "predicates/predicates_internal.h"
#include "skin/skin_internal.h"

enum { LINK_TEST = 0, POWER_TEST = 1 };

/* One record type for both roles, so a level's entries can be compacted in place into the next
 * level: as an entry, v = a k-simplex X (sorted ball indices, UINT32_MAX padded), opp the ball
 * of one of its cofaces Y = X + opp and in = 1 when Y is in K; as a simplex of a level, v and
 * in = 1 when it is in the dual complex K (opp unused). */
typedef struct simplex_rec {
    uint32_t v[4];
    uint32_t opp;
    int in;
} simplex_rec;

static int cmp_rec(const void *pa, const void *pb)
{
    return skin_key_cmp(((const simplex_rec *)pa)->v, ((const simplex_rec *)pb)->v);
}

/* The 24 permutations of 0..3 and their signs (Leibniz expansion of a determinant). A
 * determinant of order m < 4 uses the ones that fix m..3, whose signs are those of their
 * restriction to 0..m-1. */
static const unsigned char perm4[24][4] = {
    {0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {0, 3, 2, 1},
    {1, 0, 2, 3}, {1, 0, 3, 2}, {1, 2, 0, 3}, {1, 2, 3, 0}, {1, 3, 0, 2}, {1, 3, 2, 0},
    {2, 0, 1, 3}, {2, 0, 3, 1}, {2, 1, 0, 3}, {2, 1, 3, 0}, {2, 3, 0, 1}, {2, 3, 1, 0},
    {3, 0, 1, 2}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 1, 2, 0}, {3, 2, 0, 1}, {3, 2, 1, 0}};
static const signed char perm4_sign[24] = {1, -1, -1, 1, 1, -1, -1, 1, 1, -1, -1, 1,
                                           1, -1, -1, 1, 1, -1, -1, 1, 1, -1, -1, 1};

static int perm_fixes_tail(int q, int m)
{
    for (int i = m; i < 4; i++)
        if (perm4[q][i] != i) return 0;
    return 1;
}

/* ---- the bordered determinant in floating point, certified or not ---- */

static int in_filter_range(double v)
{
    double a = fabs(v);
    return a == 0 || (a >= 1e-30 && a <= 1e30);
}

/* Sign of the bordered determinant of simplex x[0..k] (mode LINK_TEST with ball b, or
 * POWER_TEST) when floating point certifies it, else 2. Error bound: every entry is a sum of at
 * most 5 products or differences of input values, computed with relative error <= 8u of the sum
 * of the absolute values of its terms, A_ij (u = 2^-53; the differences e_i carry u each). A
 * Leibniz term of m <= 4 entries then errs by <= ((1 + 8u)^4 (1 + u)^3 - 1) prod A <= 36u
 * prod A, and the sum of at most 24 terms adds <= 24u (1 + 36u) sum prod A. So
 * |D_float - D| <= 61u P with P = sum over permutations of prod A; the filter asks for
 * |D_float| > 1e-13 P (about 15 times that bound, which also covers the rounding of P). The
 * bound assumes no underflow or overflow: every nonzero |e_ic| and sqrt|w| must lie in
 * [1e-30, 1e30], so every product of up to 8 of them stays within [1e-240, 1e240]; other
 * inputs go to the exact stage. */
static int bordered_filter(const double *balls, const uint32_t *x, int k, int mode, uint32_t b)
{
    const double *z0 = balls + 4 * (size_t)x[0];
    double e[4][3], m[4][4], a[4][4];
    int rows = k + (mode == LINK_TEST);
    for (int i = 0; i < rows; i++) {
        const double *zi = balls + 4 * (size_t)(i < k ? x[i + 1] : b);
        for (int c = 0; c < 3; c++) {
            e[i][c] = zi[c] - z0[c];
            if (!in_filter_range(e[i][c])) return 2;
        }
        if (!in_filter_range(sqrt(fabs(zi[3])))) return 2;
    }
    if (!in_filter_range(sqrt(fabs(z0[3])))) return 2;
    /* s_i and its magnitude, for the k edges and (LINK_TEST) the ball b in row k */
    double s[4], sa[4];
    for (int i = 0; i < rows; i++) {
        const double *zi = balls + 4 * (size_t)(i < k ? x[i + 1] : b);
        double ee = e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2];
        s[i] = ee - zi[3] + z0[3];
        sa[i] = ee + fabs(zi[3]) + fabs(z0[3]);
    }
    for (int i = 0; i < k; i++) {
        for (int j = 0; j < k; j++) {
            m[i][j] = e[i][0] * e[j][0] + e[i][1] * e[j][1] + e[i][2] * e[j][2];
            a[i][j] = fabs(e[i][0] * e[j][0]) + fabs(e[i][1] * e[j][1]) + fabs(e[i][2] * e[j][2]);
        }
        if (mode == LINK_TEST) {
            m[i][k] = e[i][0] * e[k][0] + e[i][1] * e[k][1] + e[i][2] * e[k][2];
            a[i][k] = fabs(e[i][0] * e[k][0]) + fabs(e[i][1] * e[k][1]) + fabs(e[i][2] * e[k][2]);
        } else {
            m[i][k] = s[i];
            a[i][k] = sa[i];
        }
        m[k][i] = s[i];
        a[k][i] = sa[i];
    }
    if (mode == LINK_TEST) {
        m[k][k] = s[k];
        a[k][k] = sa[k];
    } else {
        m[k][k] = 4 * z0[3];
        a[k][k] = fabs(m[k][k]);
    }
    double d = 0, p = 0;
    for (int q = 0; q < 24; q++) {
        if (!perm_fixes_tail(q, k + 1)) continue;
        double prod = perm4_sign[q], mag = 1;
        for (int i = 0; i <= k; i++) {
            prod *= m[i][perm4[q][i]];
            mag *= a[i][perm4[q][i]];
        }
        d += prod;
        p += mag;
    }
    if (!isfinite(d) || !isfinite(p)) return 2;
    if (fabs(d) > 1e-13 * p) return d > 0 ? 1 : -1;
    if (p == 0) return 0; /* every entry and term is exactly zero */
    return 2;
}

/* ---- the bordered determinant in big integers ---- */

typedef struct arena {
    uint32_t *pool;
    int limbs, used;
} arena;

static fl_big take(arena *A)
{
    fl_big r = {A->pool + (size_t)A->used++ * (size_t)A->limbs, 0, 0};
    return r;
}

static void big_dot(fl_big *r, fl_big *tmp, const fl_big *u, const fl_big *v)
{
    r->len = 0;
    r->neg = 0;
    for (int c = 0; c < 3; c++) {
        fl_big_mul(tmp, &u[c], &v[c]);
        fl_big_add(r, r, tmp);
    }
}

/* Exact sign of the same determinant, or 2 when out of memory. Every coordinate is an integer
 * multiple of 2^emin and every weight of 2^(2 emin) (emin the smallest lowest-set-bit exponent,
 * halved for the weights), so scaling them by 2^-emin and 2^-2emin makes every entry an integer
 * and multiplies the determinant by a positive power of two. Sizes: a scaled coordinate or
 * square root of a weight has at most `bits` bits; a difference bits + 1, an entry
 * 2 bits + 6 (three products and two weights), a Leibniz term of four entries 8 bits + 24,
 * the sum of 24 terms 5 more. */
static int bordered_exact(const double *balls, const uint32_t *x, int k, int mode, uint32_t b)
{
    int nb = k + 1 + (mode == LINK_TEST);
    const double *z[5];
    for (int i = 0; i <= k; i++)
        z[i] = balls + 4 * (size_t)x[i];
    if (mode == LINK_TEST) z[k + 1] = balls + 4 * (size_t)b;
    int emin = 4000, ew = 4000, top = -4000;
    for (int i = 0; i < nb; i++) {
        for (int c = 0; c < 3; c++)
            if (z[i][c] != 0) {
                int lo = fl_big_low_exponent(z[i][c]);
                emin = lo < emin ? lo : emin;
                top = ilogb(z[i][c]) > top ? ilogb(z[i][c]) : top;
            }
        double w = z[i][3];
        if (w != 0) {
            int lo = fl_big_low_exponent(w);
            ew = lo < ew ? lo : ew;
            int half = (ilogb(w) + 1) / 2 + 1;
            top = half > top ? half : top;
        }
    }
    if (ew != 4000) {
        int half = ew >= 0 ? ew / 2 : -((-ew + 1) / 2); /* floor(ew / 2) */
        emin = half < emin ? half : emin;
    }
    if (emin == 4000) emin = 0; /* every input zero */
    if (top == -4000) top = 0;
    int bits = top + 2 - emin;
    int limbs = (8 * bits + 64) / 32 + 4;
    int need_in = (1024 - 2 * emin) / 32 + 4;
    if (need_in > limbs) limbs = need_in;
    arena A = {NULL, limbs, 0};
    A.pool = malloc((size_t)64 * (size_t)limbs * sizeof(uint32_t));
    if (!A.pool) return 2;
    fl_big P[5][3], W[5], E[4][3], S[4], M[4][4];
    for (int i = 0; i < nb; i++) {
        for (int c = 0; c < 3; c++) {
            P[i][c] = take(&A);
            fl_big_set_double(&P[i][c], z[i][c], emin);
        }
        W[i] = take(&A);
        fl_big_set_double(&W[i], z[i][3], 2 * emin);
    }
    fl_big tmp = take(&A), tmp2 = take(&A), acc = take(&A);
    int rows = nb - 1; /* e_1 .. e_k and, for LINK_TEST, e_b */
    for (int i = 0; i < rows; i++) {
        for (int c = 0; c < 3; c++) {
            E[i][c] = take(&A);
            fl_big_sub(&E[i][c], &P[i + 1][c], &P[0][c]);
        }
        S[i] = take(&A);
        big_dot(&S[i], &tmp, E[i], E[i]);
        fl_big_sub(&S[i], &S[i], &W[i + 1]);
        fl_big_add(&S[i], &S[i], &W[0]);
    }
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++)
            M[i][j] = take(&A);
    for (int i = 0; i < k; i++) {
        for (int j = 0; j < k; j++)
            big_dot(&M[i][j], &tmp, E[i], E[j]);
        if (mode == LINK_TEST)
            big_dot(&M[i][k], &tmp, E[i], E[k]);
        else
            fl_big_add(&M[i][k], &S[i], &M[i][k]); /* M[i][k] starts at zero */
        fl_big_add(&M[k][i], &S[i], &M[k][i]);
    }
    if (mode == LINK_TEST) {
        fl_big_add(&M[k][k], &S[k], &M[k][k]);
    } else {
        fl_big_add(&M[k][k], &W[0], &W[0]);
        fl_big_add(&M[k][k], &M[k][k], &M[k][k]);
    }
    fl_big zero = take(&A);
    for (int q = 0; q < 24; q++) {
        if (!perm_fixes_tail(q, k + 1)) continue;
        fl_big_add(&tmp, &M[0][perm4[q][0]], &zero);
        for (int i = 1; i <= k; i++) { /* tmp2 = tmp * entry, then swap the two slots */
            fl_big_mul(&tmp2, &tmp, &M[i][perm4[q][i]]);
            fl_big swap = tmp;
            tmp = tmp2;
            tmp2 = swap;
        }
        if (perm4_sign[q] > 0)
            fl_big_add(&acc, &acc, &tmp);
        else
            fl_big_sub(&acc, &acc, &tmp);
    }
    int sign = fl_big_sign(&acc);
    free(A.pool);
    return sign;
}

/* Sign of the bordered determinant: the filter, else the exact stage (2: out of memory). */
static int bordered_sign(const double *balls, const uint32_t *x, int k, int mode, uint32_t b)
{
    int s = bordered_filter(balls, x, k, mode, b);
    return s != 2 ? s : bordered_exact(balls, x, k, mode, b);
}

/* ---- the dual complex, from tetrahedra down to vertices ---- */

/* X = group[0].v with its cofaces group[0..count-1]: 1 when X is in K, 0 when not, -1 when
 * out of memory. */
static int decide(const double *balls, const simplex_rec *group, size_t count, int k)
{
    for (size_t i = 0; i < count; i++)
        if (group[i].in) return 1; /* nu_Y lies in nu_X, where pi_X = pi_Y < 0 */
    for (size_t i = 0; i < count; i++) {
        int s = bordered_sign(balls, group[0].v, k, LINK_TEST, group[i].opp);
        if (s == 2) return -1;
        if (s < 0) return 0; /* f beyond the facet of the coface: the minimum is on the boundary */
    }
    int s = bordered_sign(balls, group[0].v, k, POWER_TEST, 0);
    if (s == 2) return -1;
    return s > 0; /* det sign is the opposite of pi_X(f)'s: X in K iff pi_X(f) < 0 */
}

static void sort4(uint32_t *v)
{
    for (int i = 1; i < 4; i++)
        for (int j = i; j > 0 && v[j - 1] > v[j]; j--) {
            uint32_t t = v[j];
            v[j] = v[j - 1];
            v[j - 1] = t;
        }
}

/* chi(K) from the tetrahedra of rt over `balls` (auxiliary balls included: they are decided
 * like the others and never come out in K). */
static fl_status dual_euler(const double *balls, const fl_rt3 *rt, long long *chi, fl_error *err)
{
    size_t count = rt->tet_count;
    simplex_rec *level = fl_alloc_array(count ? count : 1, sizeof *level);
    if (!level) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "balls union euler: out of memory");
    long long sum = 0;
    /* tetrahedra: nu_X is the point f itself */
    for (size_t t = 0; t < count; t++) {
        memcpy(level[t].v, rt->tet + 4 * t, 4 * sizeof(uint32_t));
        sort4(level[t].v);
        int s = bordered_sign(balls, level[t].v, 3, POWER_TEST, 0);
        if (s == 2) goto nomem;
        level[t].in = s > 0;
        sum -= level[t].in;
    }
    for (int k = 2; k >= 0; k--) {
        /* every (k+1)-simplex Y gives each of its k + 2 facets X the entry (X, Y \ X, Y in K) */
        size_t m = count * (size_t)(k + 2), u = 0;
        simplex_rec *e = fl_alloc_array(m ? m : 1, sizeof *e);
        if (!e) goto nomem;
        for (size_t y = 0; y < count; y++)
            for (int drop = 0; drop <= k + 1; drop++) {
                simplex_rec *c = &e[u++];
                int j = 0;
                for (int i = 0; i <= k + 1; i++)
                    if (i != drop) c->v[j++] = level[y].v[i];
                for (; j < 4; j++)
                    c->v[j] = UINT32_MAX;
                c->opp = level[y].v[drop];
                c->in = level[y].in;
            }
        free(level);
        level = e;
        qsort(e, m, sizeof *e, cmp_rec);
        /* decide each group of equal X and compact the k-simplices into the front of e (record
         * `count` <= the group's first index, already read) */
        count = 0;
        for (size_t i = 0; i < m;) {
            size_t j = i + 1;
            while (j < m && !skin_key_cmp(e[j].v, e[i].v))
                j++;
            int in = decide(balls, e + i, j - i, k);
            if (in < 0) goto nomem;
            memmove(e[count].v, e[i].v, sizeof e[count].v);
            e[count++].in = in;
            if (in) sum += k % 2 ? -1 : 1;
            i = j;
        }
    }
    free(level);
    *chi = sum;
    return FL_OK;
nomem:
    free(level);
    return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "balls union euler: out of memory");
}

/* The balls plus four auxiliary ones at the corners of a regular tetrahedron of half-size L
 * around the centres' box, L a power of two at least 4 (box diagonal + largest radius + 1 +
 * largest coordinate of the box centre),
 * weight -16 L^2: their power |x - c|^2 + 16 L^2 is positive everywhere, and their centres lie
 * outside the hull of the others, so they are vertices and the triangulation is 3D. NULL when
 * out of memory or when L overflows (*too_big set). */
static double *with_auxiliary(const double *xyzw, size_t n, int *too_big)
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    double wmax = 0;
    for (size_t i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], xyzw[4 * i + c]);
            hi[c] = fmax(hi[c], xyzw[4 * i + c]);
        }
        wmax = fmax(wmax, xyzw[4 * i + 3]);
    }
    double mid[3], diag = 0, far = 0;
    for (int c = 0; c < 3; c++) {
        mid[c] = n ? 0.5 * lo[c] + 0.5 * hi[c] : 0;
        diag += n ? (hi[c] - lo[c]) * (hi[c] - lo[c]) : 0;
        far = fmax(far, fabs(mid[c]));
    }
    /* L also exceeds the coordinates themselves, so mid +- L does not round back onto mid (a
     * small set far from the origin would get a flat or repeated auxiliary tetrahedron) */
    double size = 4 * (sqrt(diag) + sqrt(wmax) + 1 + far);
    double L = isfinite(size) ? exp2(ceil(log2(size))) : HUGE_VAL;
    *too_big = !(L < 1e120); /* inputs are <= 1e100, so this holds; 16 L^2 stays finite */
    if (*too_big) return NULL;
    double *all = fl_alloc_array(n + 4, 4 * sizeof(double));
    if (!all) return NULL;
    if (n) memcpy(all, xyzw, n * 4 * sizeof(double));
    static const double corner[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (int j = 0; j < 4; j++) {
        for (int c = 0; c < 3; c++)
            all[4 * (n + j) + c] = mid[c] + L * corner[j][c];
        all[4 * (n + j) + 3] = -16 * L * L;
    }
    return all;
}

fl_status fl_balls_union_euler(const double *xyzw, size_t n, long long *chi, fl_error *err)
{
    fl_error_clear(err);
    if (!chi || (n && !xyzw))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "balls union euler: NULL argument");
    *chi = 0;
    for (size_t i = 0; i < 4 * n; i++)
        if (!isfinite(xyzw[i]) || fabs(xyzw[i]) > 1e100)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "balls union euler: ball %zu has a NaN, infinite or > 1e100 value",
                           i / 4);
    if (n > UINT32_MAX - 8)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "balls union euler: too many balls (%zu)", n);
    int positive = 0;
    for (size_t i = 0; i < n && !positive; i++)
        positive = xyzw[4 * i + 3] > 0;
    if (!positive) return FL_OK; /* the union is empty */
    fl_rt3 rt;
    fl_error rt_err;
    fl_status st = fl_rt3_build(xyzw, n, NULL, &rt, &rt_err);
    if (st == FL_OK) {
        st = dual_euler(xyzw, &rt, chi, err);
        fl_rt3_free(&rt);
        return st;
    }
    if (st == FL_ERR_NOMEM || st == FL_ERR_USAGE) {
        if (err) *err = rt_err;
        return st;
    }
    /* fewer than 4 distinct centres or all in a plane (FL_ERR_INPUT or FL_ERR_ALGORITHM from
     * fl_rt3_build): add the auxiliary balls; a failure then is reported as it is */
    int too_big = 0;
    double *all = with_auxiliary(xyzw, n, &too_big);
    if (!all)
        return too_big ? fl_fail(err, FL_ERR_INPUT, NULL, -1,
                                 "balls union euler: the balls' extent is too large")
                       : fl_fail(err, FL_ERR_NOMEM, NULL, -1, "balls union euler: out of memory");
    st = fl_rt3_build(all, n + 4, NULL, &rt, &rt_err);
    if (st == FL_OK) {
        st = dual_euler(all, &rt, chi, err);
        fl_rt3_free(&rt);
    } else if (err) {
        *err = rt_err;
    }
    free(all);
    return st;
}

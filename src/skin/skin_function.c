/* The skin function G of a ball set (Cheng & Tan §6.1; Edelsbrunner's skin).
 *
 * G(x) = min over b in conv(B) of pi_{b^t}(x), the power distance of x to the shrunk ball.
 * Writing the combination's centre z and its lifted height L(z) (the lower hull of the lifted
 * balls, i.e. the regular triangulation), the function minimised is convex in z for t < 1 and
 * its minimiser lies in the relative interior of one simplex X of the regular triangulation.
 * There, with focus f and orthogonal weight w of X, and x - f = p + q split into the parts
 * parallel and orthogonal to aff(X):
 *
 *     G(x) = |q|^2 - t/(1-t) |p|^2 + t w,   minimiser z* = f + p / (1-t) in X,
 *
 * which is the quadric of the mixed cell (1-t) X + t nu_X (docs/skin.md derives it). Every
 * simplex whose z* lies in it gives the power distance of an actual member of conv(B), hence a
 * value >= G(x); the minimising simplex gives G(x). So the minimum over candidate simplices is
 * G(x) as soon as the candidates contain the minimising one, and extra candidates are harmless.
 * If G(x) < 0, the minimiser's centre z* has |x - z*|^2 < t w(z*), and w(z*) is at most the
 * largest weight of X's balls (on X the weight |z|^2 - L(z) is convex in z, L affine, so it
 * peaks at a vertex). So only simplices with a positive ball can hold the minimiser of a
 * negative G, and only within their own reach sqrt(t max w): the index lists each simplex
 * near itself only, not within the reach of the largest ball of the set (which made every
 * list hold most simplices when a few balls are large, as in the eps-approximation's B*). */
#include <float.h>
#include <math.h>
#ifdef FL_SKIN_WALK_STATS
#include <stdio.h>
#endif
#include <stdatomic.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "skin/skin_internal.h"

/* Inverts the k x k symmetric Gram matrix g (Gauss-Jordan with partial pivoting). Returns -1
 * when it is singular relative to its diagonal (affinely dependent centres). */
static int invert_gram(int k, const double g[3][3], double inv[3][3])
{
    double m[3][6];
    double scale = 0;
    for (int i = 0; i < k; i++) {
        for (int j = 0; j < k; j++) {
            m[i][j] = g[i][j];
            m[i][k + j] = i == j;
        }
        if (g[i][i] > scale) scale = g[i][i];
    }
    for (int c = 0; c < k; c++) {
        int piv = c;
        for (int r = c + 1; r < k; r++)
            if (fabs(m[r][c]) > fabs(m[piv][c])) piv = r;
        if (!(fabs(m[piv][c]) > 1e-12 * scale)) return -1;
        for (int j = 0; j < 2 * k; j++) {
            double tmp = m[c][j];
            m[c][j] = m[piv][j];
            m[piv][j] = tmp;
        }
        double d = m[c][c];
        for (int j = 0; j < 2 * k; j++)
            m[c][j] /= d;
        for (int r = 0; r < k; r++) {
            if (r == c) continue;
            double fct = m[r][c];
            for (int j = 0; j < 2 * k; j++)
                m[r][j] -= fct * m[c][j];
        }
    }
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++)
            inv[i][j] = m[i][k + j];
    return 0;
}

/* Fills s for the balls idx[0..k] (k+1 balls). Returns -1 for affinely dependent centres. */
int skin_simplex_setup(const double *xyzw, const uint32_t *idx, int k, skin_simplex *s)
{
    const double *b0 = xyzw + 4 * (size_t)idx[0];
    memset(s, 0, sizeof *s);
    s->k = (uint8_t)k;
    for (int i = 0; i < 4; i++)
        s->ball[i] = i <= k ? idx[i] : UINT32_MAX;
    double a[3], e[3][3], g[3][3], rhs[3];
    skin_frame(xyzw, s, a, e);
    for (int i = 0; i < k; i++) {
        for (int j = 0; j < k; j++)
            g[i][j] = e[i][0] * e[j][0] + e[i][1] * e[j][1] + e[i][2] * e[j][2];
        /* equal power to ball 0 and ball i at f = a + E eta: G eta = (|e_i|^2 - w_i + w_0)/2 */
        rhs[i] = 0.5 * (g[i][i] - xyzw[4 * (size_t)idx[i + 1] + 3] + b0[3]);
    }
    if (k > 0 && invert_gram(k, g, s->ginv)) return -1;
    /* condition estimate k |G|_max |G^-1|_max: above 1e10 the coordinates mu lose all but a
     * few digits, so the mixed-cell walk does not trust them (skin_cell.c) */
    double gmax = 0, imax = 0;
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++) {
            gmax = fmax(gmax, fabs(g[i][j]));
            imax = fmax(imax, fabs(s->ginv[i][j]));
        }
    s->shaky = !(k * gmax * imax <= 1e10) ? SKIN_SHAKY_COND : 0;
    for (int i = 0; i < k; i++) {
        double eta = 0;
        for (int j = 0; j < k; j++)
            eta += s->ginv[i][j] * rhs[j];
        s->mu_f[i] = eta;
    }
    return 0;
}

/* skin_simplex_value (skin_internal.h): skin_combination_value at X's minimiser z*, its
 * barycentric coordinates clamped to >= 0: never below G(x) beyond rounding, and G(x) itself
 * when z* lies in X. Until round 18 a z* more than 1e-12 outside X gave HUGE_VAL;
 * but for a needle simplex (Gram condition ~1e10 and more) the computed coordinates are off by
 * far more than that, and the true minimiser was rejected: G = 0.94 where it is 8e-7
 * (tests/skin/test_skin_needle.c). A clamped candidate is still a member of conv(B), so
 * accepting every candidate keeps the scan's minimum an upper bound that the minimiser's
 * simplex makes exact. */
double skin_simplex_value(const fl_skin_function *sk, const skin_simplex *s, const double x[3],
                          double grad[3])
{
    double t = sk->t, a[3], e[3][3], d[3], mu[4], xi[3] = {0, 0, 0};
    skin_frame(sk->balls, s, a, e);
    for (int c = 0; c < 3; c++)
        d[c] = x[c] - a[c];
    double et[3];
    for (int i = 0; i < s->k; i++)
        et[i] = e[i][0] * d[0] + e[i][1] * d[1] + e[i][2] * d[2];
    double sum = 0;
    for (int i = 0; i < s->k; i++) {
        for (int j = 0; j < s->k; j++)
            xi[i] += s->ginv[i][j] * et[j];
        mu[i + 1] = s->mu_f[i] + (xi[i] - s->mu_f[i]) / (1 - t);
        sum += mu[i + 1];
    }
    mu[0] = 1 - sum;
    if (grad) { /* envelope theorem: grad G = 2 (x - z*), z* = a + sum_i mu_i e_(i-1) */
        for (int c = 0; c < 3; c++) {
            grad[c] = d[c];
            for (int i = 1; i <= s->k; i++)
                grad[c] -= mu[i] * e[i - 1][c];
            grad[c] *= 2;
        }
    }
    return skin_combination_value(sk->balls, s, t, a, e, mu, x);
}

int skin_index_cell(const fl_skin_function *skin, const double x[3], size_t *cell)
{
    size_t id = 0;
    for (int c = 2; c >= 0; c--) {
        double u = floor((x[c] - skin->origin[c]) / skin->cell);
        if (!(u >= 0 && u < (double)skin->dims[c])) return 0;
        id = id * skin->dims[c] + (size_t)u;
    }
    *cell = id;
    return 1;
}

/* The minimum over the candidates the index lists at x (G wherever G < 0 and near the
 * simplices with a positive ball, HUGE_VAL where nothing is listed); the fallback and test
 * reference of the mixed-cell walk (skin_cell.c). */
double skin_value_scan(const fl_skin_function *skin, const double x[3])
{
    size_t cell = 0;
    if (!skin_index_cell(skin, x, &cell)) return HUGE_VAL;
    double best = HUGE_VAL;
    const float *box = skin->scan_box;
    float xf[3][2]; /* x rounded down and up to float: the box test is conservative */
    for (int c = 0; box && c < 3; c++) {
        xf[c][0] = (float)x[c];
        if ((double)xf[c][0] > x[c]) xf[c][0] = nextafterf(xf[c][0], -HUGE_VALF);
        xf[c][1] = (float)x[c];
        if ((double)xf[c][1] < x[c]) xf[c][1] = nextafterf(xf[c][1], HUGE_VALF);
    }
    for (size_t i = skin->cell_start[cell]; i < skin->cell_start[cell + 1]; i++) {
        uint32_t id = skin->cell_item[i];
        if (box) { /* x outside X's registration box: X is not the minimiser of a G <= 0 */
            const float *b = box + 6 * (size_t)id;
            if (xf[0][1] < b[0] || xf[0][0] > b[3] || xf[1][1] < b[1] || xf[1][0] > b[4] ||
                xf[2][1] < b[2] || xf[2][0] > b[5])
                continue;
        }
#ifdef FL_SKIN_WALK_STATS
        {
            extern _Atomic size_t skin_stat_scan_evaluated;
            skin_stat_scan_evaluated++;
        }
#endif
        double v = skin_simplex_value(skin, &skin->simplex[id], x, NULL);
        if (v < best) best = v;
    }
    return best;
}

void fl_skin_function_free(fl_skin_function *skin)
{
    if (!skin) return;
    free(skin->simplex);
    free(skin->cell_start);
    free(skin->cell_item);
    free(skin->scan_box);
    free(skin->balls);
    free(skin->link_start);
    free(skin->link);
    free(skin->dropped);
    free(skin->dropped_link_start);
    free(skin->hint);
    free(skin->first_stored);
    free(skin->first_dropped);
    free(skin->cell_seed);
    free(skin);
}

/* ---- candidate simplices ---- */

static void simplex_box(const double *balls, const skin_simplex *s, double lo[3], double hi[3]);
static double dot3(const double *u, const double *v);
static void cross3(const double *u, const double *v, double *w);

/* The box where the index lists s: its mixed cell's box (1-t) box(X) + t box(nu_X) cut to the
 * reach box when s->box_exact (nu_lo/nu_hi bound its power face, from the Voronoi vertices or
 * clipped, skin_clip.c), the reach box alone otherwise; empty on some axis (lo > hi) when the
 * two do not meet. */
static void reg_box(const double *balls, double t, const skin_simplex *s, double lo[3],
                    double hi[3])
{
    double g = SKIN_REACH_MARGIN * skin_reach(balls, s, t);
    simplex_box(balls, s, lo, hi);
    for (int c = 0; c < 3; c++) {
        double xlo = lo[c], xhi = hi[c];
        lo[c] = xlo - g;
        hi[c] = xhi + g;
        if (!s->box_exact) continue;
        /* the mixed cell is (1-t) X + t nu_X; the slack covers the rounding of this sum */
        double mlo = (1 - t) * xlo + t * s->nu_lo[c], mhi = (1 - t) * xhi + t * s->nu_hi[c];
        double slack = 1e-12 * (fabs(mlo) + fabs(mhi));
        lo[c] = fmax(lo[c], mlo - slack);
        hi[c] = fmin(hi[c], mhi + slack);
    }
}

/* Adds the simplex of the balls idx[0..k], with the box of its power face when nu_lo/nu_hi
 * bound it (NULL: unbounded or untrustworthy; the index then uses the reach box, reg_box). */
static int add_simplex(fl_vec *v, const double *xyzw, const uint32_t *idx, int k,
                       const double *nu_lo, const double *nu_hi)
{
    skin_simplex s;
    if (skin_simplex_setup(xyzw, idx, k, &s)) return 0; /* affinely dependent: never a minimiser */
    s.box_exact = nu_lo != NULL ? SKIN_BOX_VORONOI : 0;
    for (int c = 0; nu_lo && c < 3; c++) {
        s.nu_lo[c] = nu_lo[c];
        s.nu_hi[c] = nu_hi[c];
    }
    return fl_vec_push(v, &s, 1);
}

/* Few balls: every subset of at most 4 balls is a candidate (a superset of the regular
 * triangulation's simplices, so the minimum is still G; no triangulation, no degeneracy). */
static int subsets(fl_vec *v, const double *xyzw, size_t n)
{
    uint32_t idx[4];
    for (uint32_t mask = 1; mask < (1u << n); mask++) {
        int k = 0;
        for (uint32_t i = 0; i < n && k <= 4; i++)
            if (mask >> i & 1) {
                if (k < 4) idx[k] = i;
                k++;
            }
        if (k <= 4 && add_simplex(v, xyzw, idx, k - 1, NULL, NULL)) return -1;
    }
    return 0;
}

/* A simplex of the regular triangulation as a face of one tetrahedron (tet), or of a hull
 * face (tet = UINT32_MAX: its power face nu_X is unbounded). */
typedef struct rt_tuple {
    uint32_t v[4]; /* sorted ball indices, UINT32_MAX padding */
    /* the tetrahedron it comes from, or RT_HULL | the hull face (20 bytes a tuple, not 24 with
     * two fields: the npm bunny's B* has 3.7e7 of them at the mixed complex's memory peak) */
    uint32_t src;
} rt_tuple;
#define RT_HULL 0x80000000u
#define TUPLE_TET(u) ((u)->src & RT_HULL ? UINT32_MAX : (u)->src)
#define TUPLE_HULL(u) ((u)->src & RT_HULL ? (u)->src & ~RT_HULL : UINT32_MAX)

static int cmp_tuple(const void *pa, const void *pb)
{
    return skin_key_cmp(((const rt_tuple *)pa)->v, ((const rt_tuple *)pb)->v);
}

static void sort_small(uint32_t *a, int n)
{
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && a[j - 1] > a[j]; j--) {
            uint32_t tmp = a[j];
            a[j] = a[j - 1];
            a[j - 1] = tmp;
        }
}

/* The Voronoi (power) vertex of tetrahedron t, the centre of the ball orthogonal to its four
 * balls, into o[0..2], and in o[3] a bound on its rounding error per coordinate; o[3] = -1 when
 * the tetrahedron is too flat for the bound to mean anything. With e_i = z_i - z_0 the centre
 * solves 2 e_i.x = |e_i|^2 - w_i + w_0 (Cramer). Each computed determinant or numerator is off
 * by at most a few ulps of the sum of its terms' absolute values (D for the denominator, M_k for
 * numerator k), so |dx_k| <= 16 eps (M_k + |x_k| D) / |det| when |det| >> eps D. Symmetric
 * inputs (the cube's protecting balls mirrored across an edge) give slivers whose four centres
 * are coplanar up to the input's last bit: their vertex is decided by rounding noise, and
 * their faces fall back to the reach box. */
static void voronoi_vertex(const double *xyzw, const uint32_t *t, double o[4])
{
    const double *p[4];
    for (int i = 0; i < 4; i++)
        p[i] = xyzw + 4 * (size_t)t[i];
    double e[3][3], r[3], ra[3];
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++)
            e[i][k] = p[i + 1][k] - p[0][k];
        double l2 = e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2];
        r[i] = l2 - p[i + 1][3] + p[0][3];
        ra[i] = l2 + fabs(p[i + 1][3]) + fabs(p[0][3]);
    }
    double c[3][3], ca[3][3]; /* cofactor vectors e1 x e2, e2 x e0, e0 x e1 and their bounds */
    for (int j = 0; j < 3; j++) {
        const double *u = e[(j + 1) % 3], *w = e[(j + 2) % 3];
        for (int k = 0; k < 3; k++) {
            int a = (k + 1) % 3, b = (k + 2) % 3;
            c[j][k] = u[a] * w[b] - u[b] * w[a];
            ca[j][k] = fabs(u[a] * w[b]) + fabs(u[b] * w[a]);
        }
    }
    double det = 2 * (e[0][0] * c[0][0] + e[0][1] * c[0][1] + e[0][2] * c[0][2]);
    double dabs = 2 * (fabs(e[0][0]) * ca[0][0] + fabs(e[0][1]) * ca[0][1] +
                       fabs(e[0][2]) * ca[0][2]);
    o[3] = -1;
    if (!(fabs(det) > 1e-12 * dabs)) return;
    double pad = 0;
    for (int k = 0; k < 3; k++) {
        double x = (r[0] * c[0][k] + r[1] * c[1][k] + r[2] * c[2][k]) / det;
        double m = ra[0] * ca[0][k] + ra[1] * ca[1][k] + ra[2] * ca[2][k];
        o[k] = p[0][k] + x;
        pad = fmax(pad, 32 * DBL_EPSILON * (m + fabs(x) * dabs) / fabs(det) +
                            4 * DBL_EPSILON * fabs(o[k]));
    }
    if (isfinite(o[0] + o[1] + o[2] + pad)) o[3] = pad;
}

/* 1 when some ball of the (sorted, padded) key v has a positive weight: the only simplices
 * the mesher needs (skin_function_new_mesher). A finer test, t w_X > (1-t) max w_i (then G > 0
 * on the whole mixed cell too: there G = t^2 pi_X(v) - t (1-t) w(z) with pi_X >= w_X on nu_X),
 * would drop only 50839 of the 37 million positive tuples of the npm bunny's B*: not done. */
static int has_positive_ball(const double *xyzw, const uint32_t v[4])
{
    for (int i = 0; i < 4 && v[i] != UINT32_MAX; i++)
        if (xyzw[4 * (size_t)v[i] + 3] > 0) return 1;
    return 0;
}

/* The number of faces of the nv balls v with a positive ball: all but those of the
 * non-positive balls alone. */
static size_t positive_faces(const double *xyzw, const uint32_t *v, int nv)
{
    int neg = 0;
    for (int i = 0; i < nv; i++)
        neg += !(xyzw[4 * (size_t)v[i] + 3] > 0);
    return ((size_t)1 << nv) - ((size_t)1 << neg);
}

/* The number of faces of the nv balls v without a positive ball whose smallest ball lies in
 * [lo, hi) (the dropped simplices of one chunk, rt_tuples' mode TUPLES_DROPPED). */
static size_t dropped_faces(const double *xyzw, const uint32_t *v, int nv, uint32_t lo,
                            uint32_t hi)
{
    size_t count = 0;
    for (uint32_t mask = 1; mask < (1u << nv); mask++) {
        uint32_t least = UINT32_MAX;
        int pos = 0;
        for (int i = 0; i < nv; i++)
            if (mask >> i & 1) {
                pos |= xyzw[4 * (size_t)v[i] + 3] > 0;
                least = v[i] < least ? v[i] : least;
            }
        count += !pos && least >= lo && least < hi;
    }
    return count;
}

enum { TUPLES_ALL, TUPLES_POSITIVE, TUPLES_DROPPED };

/* The tuples of rt: the 15 faces of every tetrahedron and the 7 faces of every hull face; with
 * TUPLES_POSITIVE, only the faces with a positive ball (skin_function_new_mesher); with
 * TUPLES_DROPPED only the others whose smallest ball lies in [lo, hi) (in chunks: all 9e7
 * tuples of B* of the bunny would be 1.8 GB). */
static rt_tuple *rt_tuples(const fl_rt3 *rt, const double *xyzw, int mode, uint32_t lo,
                           uint32_t hi, size_t *count)
{
    size_t n15 = rt->tet_count * 15, n7 = rt->hull_face_count * 7;
    if (n15 / 15 != rt->tet_count || n15 + n7 < n15) return NULL;
    size_t total = n15 + n7;
    if (mode == TUPLES_POSITIVE) { /* count first: all tuples of B* of the bunny are 1.8 GB */
        total = 0;
        for (size_t q = 0; q < rt->tet_count; q++)
            total += positive_faces(xyzw, rt->tet + 4 * q, 4);
        for (size_t q = 0; q < rt->hull_face_count; q++)
            total += positive_faces(xyzw, rt->hull_faces + 3 * q, 3);
    } else if (mode == TUPLES_DROPPED) {
        total = 0;
        for (size_t q = 0; q < rt->tet_count; q++)
            total += dropped_faces(xyzw, rt->tet + 4 * q, 4, lo, hi);
        for (size_t q = 0; q < rt->hull_face_count; q++)
            total += dropped_faces(xyzw, rt->hull_faces + 3 * q, 3, lo, hi);
    }
    rt_tuple *tup = fl_alloc_array(total + 1, sizeof(rt_tuple));
    if (!tup) return NULL;
    size_t m = 0;
    for (int pass = 0; pass < 2; pass++) {
        size_t items = pass ? rt->hull_face_count : rt->tet_count;
        int nv = pass ? 3 : 4;
        const uint32_t *src = pass ? rt->hull_faces : rt->tet;
        for (size_t q = 0; q < items; q++)
            for (uint32_t mask = 1; mask < (1u << nv); mask++) {
                rt_tuple *u = tup + m++;
                int k = 0;
                for (int i = 0; i < nv; i++)
                    if (mask >> i & 1) u->v[k++] = src[(size_t)nv * q + (size_t)i];
                sort_small(u->v, k);
                for (int i = k; i < 4; i++)
                    u->v[i] = UINT32_MAX;
                u->src = pass ? RT_HULL | (uint32_t)q : (uint32_t)q;
                if ((mode == TUPLES_POSITIVE && !has_positive_ball(xyzw, u->v)) ||
                    (mode == TUPLES_DROPPED &&
                     (has_positive_ball(xyzw, u->v) || u->v[0] < lo || u->v[0] >= hi)))
                    m--;
            }
    }
    *count = m;
    return tup;
}

/* Every simplex of the regular triangulation once, with its mixed-cell box. The power face
 * nu_X of X is the convex hull of the Voronoi vertices of the tetrahedra around X (unbounded
 * when X lies on the hull), so its box is theirs. Edelsbrunner's mixed cells (1-t) X + t nu_X
 * cover space, and on the mixed cell of X the skin function is X's quadric: with x = (1-t) a +
 * t v, a in X and v in nu_X (v - f orthogonal to aff X), the parallel part of x - f is
 * p = (1-t)(a - f), so z* = f + p/(1-t) = a lies in X. Listing X only near its mixed cell is
 * what keeps the lists short: a grid cell meets a few mixed cells, whereas the reach of a large
 * ball spans many simplices. */
/* The link of the simplex of tuples tup[i..j) (one tuple per tetrahedron holding it): the
 * balls of those tetrahedra outside X, each once, appended to link. Every coface X + b of X is
 * a face of some tetrahedron, so this is the whole link (skin_cell.c walks along it). */
static int simplex_link(fl_vec *link, const rt_tuple *tup, size_t i, size_t j,
                        const uint32_t *tets)
{
    size_t first = link->count;
    for (size_t q = i; q < j; q++) {
        uint32_t tet = TUPLE_TET(tup + q);
        if (tet == UINT32_MAX) continue; /* a hull face is a face of a tetrahedron too */
        for (int c = 0; c < 4; c++) {
            uint32_t b = tets[4 * (size_t)tet + (size_t)c];
            int seen = b == tup[i].v[0] || b == tup[i].v[1] || b == tup[i].v[2] || b == tup[i].v[3];
            const uint32_t *have = (const uint32_t *)link->data;
            for (size_t l = first; l < link->count && !seen; l++)
                seen = have[l] == b;
            if (!seen && fl_vec_push(link, &b, 1)) return -1;
        }
    }
    return 0;
}

/* Whether the power face nu_X of the simplex of tuples tup[i..j) may be degenerate, i.e.
 * the Voronoi vertices of the tetrahedra around X do not span dim = 3 - k dimensions by more
 * than their rounding pads (greedy extents: farthest point, then farthest from that line, then
 * from that plane). Cospherical balls (B* of a symmetric solid) give such faces; the link
 * half-spaces then bound a wedge through the face instead of the face, or a face thinner than
 * the rounding of the tests, so the walk must not trust X's membership test (skin_cell.c).
 * For a hull simplex (unbounded nu_X) only its finite vertices count: a face with too few of
 * them is reported too, which only sends more queries to the scan. */
static int nu_degenerate(const rt_tuple *tup, size_t i, size_t j, const double *vor,
                         const fl_rt3 *rt, const double *xyzw, int dim)
{
    enum { MAXP = 512 };
    double pts[MAXP][3], pad = 0, base[3];
    int np = 0;
    for (size_t q = i; q < j; q++) /* the finite vertices */
        if (TUPLE_TET(tup + q) != UINT32_MAX) {
            const double *o = vor + 4 * (size_t)TUPLE_TET(tup + q);
            /* a sliver's vertex is not computed (voronoi_vertex leaves o[0..2] unset): until
             * round 12 the faces of slivers came here and read those uninitialised coordinates,
             * so their flag depended on what the heap held (found by valgrind). They are no
             * longer tested (rt_simplices): their link tests are decided exactly wherever they
             * accept (skin_cell.c), and the exact tests bound nu_X itself, degenerate or not
             * (docs/skin.md, round 11), so a wedge made by rounding cannot accept x. */
            if (!(o[3] >= 0)) continue;
            if (np == MAXP) return 1;
            pad = fmax(pad, o[3]);
            for (int c = 0; c < 3; c++)
                pts[np][c] = o[c];
            np++;
        }
    for (int c = 0; c < 3; c++)
        base[c] = np ? pts[0][c] : xyzw[4 * (size_t)tup[i].v[0] + (size_t)c];
    double scale = 1 + fabs(base[0]) + fabs(base[1]) + fabs(base[2]);
    for (size_t q = i; q < j; q++) /* the rays: the normals of the hull faces around X */
        if (TUPLE_HULL(tup + q) != UINT32_MAX) {
            const uint32_t *f = rt->hull_faces + 3 * (size_t)TUPLE_HULL(tup + q);
            const double *z0 = xyzw + 4 * (size_t)f[0], *z1 = xyzw + 4 * (size_t)f[1];
            const double *z2 = xyzw + 4 * (size_t)f[2];
            double u[3], w[3], n[3];
            for (int c = 0; c < 3; c++) {
                u[c] = z1[c] - z0[c];
                w[c] = z2[c] - z0[c];
            }
            cross3(u, w, n);
            double nl = sqrt(dot3(n, n));
            if (!(nl > 0) || np == MAXP) return 1;
            for (int c = 0; c < 3; c++)
                pts[np][c] = base[c] + scale * n[c] / nl;
            np++;
        }
    if (np == 0) return 1;
    int sel[4] = {0, 0, 0, 0};
    double ext = 0;
    for (int d = 1; d <= dim; d++) {
        double best = -1, a[3], b[3], n[3];
        for (int c = 0; c < 3; c++) {
            a[c] = pts[sel[1]][c] - pts[0][c];
            b[c] = pts[sel[2]][c] - pts[0][c];
        }
        cross3(a, b, n);
        for (int q = 0; q < np; q++) {
            double u[3], m[3], dist;
            for (int c = 0; c < 3; c++)
                u[c] = pts[q][c] - pts[0][c];
            if (d == 1) {
                dist = sqrt(dot3(u, u));
            } else if (d == 2) { /* distance from the line p0 p1 */
                cross3(a, u, m);
                dist = sqrt(dot3(m, m) / dot3(a, a));
            } else { /* from the plane p0 p1 p2 */
                dist = fabs(dot3(n, u)) / sqrt(dot3(n, n));
            }
            if (dist > best) {
                best = dist;
                sel[d] = q;
            }
        }
        if (d == 1) ext = best;
        if (!(best > 64 * pad + 1e-9 * ext)) return 1;
    }
    return 0;
}

/* Every simplex of the regular triangulation once (sorted by its balls), with its mixed-cell box
 * and its link (link_start gets one entry a simplex). The power face
 * nu_X of X is the convex hull of the Voronoi vertices of the tetrahedra around X (unbounded
 * when X lies on the hull), so its box is theirs. Edelsbrunner's mixed cells (1-t) X + t nu_X
 * cover space, and on the mixed cell of X the skin function is X's quadric: with x = (1-t) a +
 * t v, a in X and v in nu_X (v - f orthogonal to aff X), the parallel part of x - f is
 * p = (1-t)(a - f), so z* = f + p/(1-t) = a lies in X. Listing X only near its mixed cell is
 * what keeps the lists short: a grid cell meets a few mixed cells, whereas the reach of a large
 * ball spans many simplices. */
/* The chunks of dropped tuples: about this many at once (168 MB; the chunks split the ball
 * indices evenly, not the tuples). */
#define SKIN_DROPPED_CHUNK ((size_t)1 << 23)

/* The simplices of rt without a positive ball (the mesher's function drops their records) as
 * light records (skin_light: key, SKIN_SHAKY_* bits) with their links appended to link, in key
 * order, in chunks of the smallest ball's index so that their tuples never all exist at once.
 * stored: the number of full records (the walk numbers the light ones after them, in 32 bits).
 * -1 when out of memory. */
static int dropped_simplices(fl_vec *dropped, fl_vec *dlink_start, fl_vec *link, const fl_rt3 *rt,
                             const double *vor, const double *xyzw, size_t n, size_t stored)
{
    size_t total = 0;
    for (size_t q = 0; q < rt->tet_count; q++)
        total += dropped_faces(xyzw, rt->tet + 4 * q, 4, 0, UINT32_MAX);
    for (size_t q = 0; q < rt->hull_face_count; q++)
        total += dropped_faces(xyzw, rt->hull_faces + 3 * q, 3, 0, UINT32_MAX);
    /* the walk's cell numbers are 32 bits with UINT32_MAX for none: without room for the
     * dropped simplices the walk scans where it reaches one, as before */
    if (total == 0 || stored + total >= UINT32_MAX - 1) return 0;
    size_t chunks = total / SKIN_DROPPED_CHUNK + 1;
    size_t first = link->count; /* the dropped links follow the stored ones */
    if (fl_vec_push(dlink_start, &first, 1)) return -1;
    for (size_t c = 0; c < chunks; c++) {
        uint32_t lo = (uint32_t)(n * c / chunks), hi = (uint32_t)(n * (c + 1) / chunks);
        size_t m = 0;
        rt_tuple *tup = rt_tuples(rt, xyzw, TUPLES_DROPPED, lo, hi, &m);
        if (!tup) return -1;
        qsort(tup, m, sizeof(rt_tuple), cmp_tuple);
        for (size_t i = 0, j; i < m; i = j) {
            int sliver = 0;
            for (j = i; j < m && !cmp_tuple(tup + i, tup + j); j++) {
                uint32_t tet = TUPLE_TET(tup + j);
                sliver |= tet != UINT32_MAX && !(vor[4 * (size_t)tet + 3] >= 0);
            }
            int k = 0;
            while (k < 4 && tup[i].v[k] != UINT32_MAX)
                k++;
            skin_simplex full;
            if (skin_simplex_setup(xyzw, tup[i].v, k - 1, &full)) continue; /* never crossed */
            skin_light l;
            memset(&l, 0, sizeof l);
            memcpy(l.ball, tup[i].v, sizeof l.ball);
            l.k = (uint8_t)(k - 1);
            l.shaky = (uint8_t)(full.shaky | (sliver ? SKIN_SHAKY_SLIVER : 0) |
                                (k - 1 < 3 && !sliver &&
                                         nu_degenerate(tup, i, j, vor, rt, xyzw, 4 - k)
                                     ? SKIN_SHAKY_DEGEN
                                     : 0));
            if (fl_vec_push(dropped, &l, 1) || simplex_link(link, tup, i, j, rt->tet) ||
                fl_vec_push(dlink_start, &link->count, 1)) {
                free(tup);
                return -1;
            }
        }
        free(tup);
    }
    return 0;
}

static fl_status rt_simplices(fl_vec *v, fl_vec *link, fl_vec *link_start, fl_vec *dropped,
                              fl_vec *dlink_start, const double *xyzw, size_t n,
                              int positive_only, fl_error *err)
{
    fl_rt3 rt;
    fl_status st = fl_rt3_build(xyzw, n, NULL, &rt, err);
    if (st == FL_ERR_ALGORITHM)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: %s", err ? err->message : "");
    if (st) return st;
    /* the adjacency is not used here: 16 bytes a tetrahedron off the memory peak */
    free(rt.adj);
    rt.adj = NULL;
    if (rt.tet_count >= RT_HULL || rt.hull_face_count >= RT_HULL) {
        size_t tets = rt.tet_count;
        fl_rt3_free(&rt);
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: too many tetrahedra (%zu)", tets);
    }
    size_t m = 0;
    rt_tuple *tup = rt_tuples(&rt, xyzw, positive_only ? TUPLES_POSITIVE : TUPLES_ALL, 0,
                              UINT32_MAX, &m);
    double *vor = fl_alloc_array(rt.tet_count + 1, 4 * sizeof(double));
    if (!tup || !vor) goto nomem;
    for (size_t i = 0; i < rt.tet_count; i++)
        voronoi_vertex(xyzw, rt.tet + 4 * i, vor + 4 * i);
    qsort(tup, m, sizeof(rt_tuple), cmp_tuple);
    /* reserve the simplices exactly: growing a vector of 10^7 simplices by doubling held the
     * old and the new copy at once (B* of the npm bunny, docs/skin.md) */
    size_t groups = 0;
    for (size_t i = 0; i < m; i++)
        groups += i == 0 || cmp_tuple(tup + i - 1, tup + i) != 0;
    if (fl_vec_reserve(v, groups) || fl_vec_reserve(link_start, groups + 1)) {
        free(tup);
        free(vor);
        fl_rt3_free(&rt);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1,
                       "skin: out of memory for the %zu simplices of the mixed complex of %zu "
                       "balls (%.0f MB)",
                       groups, n, (double)groups * (sizeof(skin_simplex) + sizeof(size_t)) / 1e6);
    }
    size_t zero = 0;
    if (fl_vec_push(link_start, &zero, 1)) goto nomem;
    for (size_t i = 0, j; i < m; i = j) {
        double nlo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, nhi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
        int bounded = 1, sliver = 0;
        for (j = i; j < m && !cmp_tuple(tup + i, tup + j); j++) {
            uint32_t tet = TUPLE_TET(tup + j);
            const double *o = tet == UINT32_MAX ? NULL : vor + 4 * (size_t)tet;
            if (!o || !(o[3] >= 0)) {
                bounded = 0;
                sliver |= o != NULL;
                continue;
            }
            for (int c = 0; c < 3; c++) {
                nlo[c] = fmin(nlo[c], o[c] - o[3]);
                nhi[c] = fmax(nhi[c], o[c] + o[3]);
            }
        }
        int k = 0;
        while (k < 4 && tup[i].v[k] != UINT32_MAX)
            k++;
        size_t before = v->count;
        if (add_simplex(v, xyzw, tup[i].v, k - 1, bounded ? nlo : NULL, nhi)) goto nomem;
        if (v->count == before) continue; /* dropped (affinely dependent): no link either */
        ((skin_simplex *)v->data)[before].shaky |=
            (uint8_t)((sliver ? SKIN_SHAKY_SLIVER : 0) |
                      (k - 1 < 3 && !sliver && nu_degenerate(tup, i, j, vor, &rt, xyzw, 4 - k)
                           ? SKIN_SHAKY_DEGEN
                           : 0));
        if (simplex_link(link, tup, i, j, rt.tet) || fl_vec_push(link_start, &link->count, 1))
            goto nomem;
    }
    free(tup);
    tup = NULL;
    /* out of memory for the light records (4 % of the stored records' bytes on sphere.off's
     * B*; ~0.4 GB for the npm bunny, docs/skin.md round 12): go on without them, the walk then
     * scans where it reaches a dropped cell, as before round 12 */
    if (positive_only && dropped_simplices(dropped, dlink_start, link, &rt, vor, xyzw, n, v->count)) {
        fl_vec_free(dropped);
        fl_vec_free(dlink_start);
        link->count = ((const size_t *)link_start->data)[link_start->count - 1];
    }
    free(vor);
    fl_rt3_free(&rt);
    return FL_OK;
nomem:
    free(tup);
    free(vor);
    fl_rt3_free(&rt);
    return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
}

/* ---- the grid index ---- */

static void simplex_box(const double *balls, const skin_simplex *s, double lo[3], double hi[3])
{
    double a[3], e[3][3];
    skin_frame(balls, s, a, e);
    for (int c = 0; c < 3; c++)
        lo[c] = hi[c] = a[c];
    for (int j = 0; j < s->k; j++)
        for (int c = 0; c < 3; c++) {
            double u = a[c] + e[j][c];
            if (u < lo[c]) lo[c] = u;
            if (u > hi[c]) hi[c] = u;
        }
}

/* Cells of the index met by the registration box (lo, hi): [c0, c1] per axis. */
static void simplex_cells(const fl_skin_function *sk, const double lo[3], const double hi[3],
                          size_t c0[3], size_t c1[3])
{
    for (int c = 0; c < 3; c++) {
        double u0 = floor((lo[c] - sk->origin[c]) / sk->cell);
        double u1 = floor((hi[c] - sk->origin[c]) / sk->cell);
        c0[c] = u0 < 0 ? 0 : (size_t)u0;
        c1[c] = u1 >= (double)sk->dims[c] ? sk->dims[c] - 1 : (size_t)u1;
    }
}

static double dot3(const double *u, const double *v)
{
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

static void cross3(const double *u, const double *v, double *w)
{
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
}

/* 0 only when c is certainly farther than d from simplex s. Conservative half-space tests: a
 * point within d of the simplex is within d outside each facet's plane (and within d of the
 * plane or line of a triangle or edge). Keeps long simplices out of the index cells they only
 * pass far from. */
static int may_be_near(const double *balls, const skin_simplex *s, const double c[3], double d)
{
    double p[4][3], v[3], sa[3], se[3][3];
    skin_frame(balls, s, sa, se);
    for (int i = 0; i <= s->k; i++)
        for (int j = 0; j < 3; j++)
            p[i][j] = sa[j] + (i ? se[i - 1][j] : 0);
    for (int j = 0; j < 3; j++)
        v[j] = c[j] - sa[j];
    if (s->k == 0) return 1;
    if (s->k == 1) {
        double len = sqrt(dot3(se[0], se[0])), along = dot3(v, se[0]) / len;
        if (along < -d || along > len + d) return 0;
        return dot3(v, v) - along * along <= d * d;
    }
    static const int face[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};
    double n[3];
    if (s->k == 2) {
        cross3(se[0], se[1], n);
        double nl = sqrt(dot3(n, n));
        if (fabs(dot3(n, v)) > d * nl) return 0;
        for (int i = 0; i < 3; i++) { /* edge p[i] p[(i+1)%3], outward in the plane */
            const double *a = p[i], *b = p[(i + 1) % 3], *o = p[(i + 2) % 3];
            double e[3], m[3], w[3], q[3];
            for (int j = 0; j < 3; j++) {
                e[j] = b[j] - a[j];
                w[j] = o[j] - a[j];
                q[j] = c[j] - a[j];
            }
            cross3(n, e, m);
            double sgn = dot3(m, w) > 0 ? -1 : 1, ml = sqrt(dot3(m, m));
            if (sgn * dot3(m, q) > d * ml) return 0;
        }
        return 1;
    }
    for (int f = 0; f < 4; f++) {
        const double *a = p[face[f][0]], *b = p[face[f][1]], *cc = p[face[f][2]];
        const double *o = p[face[f][3]];
        double e1[3], e2[3], w[3], q[3];
        for (int j = 0; j < 3; j++) {
            e1[j] = b[j] - a[j];
            e2[j] = cc[j] - a[j];
            w[j] = o[j] - a[j];
            q[j] = c[j] - a[j];
        }
        cross3(e1, e2, n);
        double sgn = dot3(n, w) > 0 ? -1 : 1, nl = sqrt(dot3(n, n));
        if (sgn * dot3(n, q) > d * nl) return 0;
    }
    return 1;
}

/* The barycentric coordinates mu_i of z* as affine functions of x (mu_0 = 1 - the others):
 * their values at c and the lengths of their gradients, for the prism test below. */
typedef struct bary_map {
    double a[3], grad[4][3], base[4], glen[4];
    int k;
} bary_map;

static void bary_setup(const fl_skin_function *sk, const skin_simplex *s, bary_map *m)
{
    double e[3][3], t = sk->t;
    m->k = s->k;
    skin_frame(sk->balls, s, m->a, e);
    /* mu_i = mu_f_i + (xi_i - mu_f_i) / (1 - t), xi = ginv E^T (x - a): i = 1..k */
    double sum[3] = {0, 0, 0}, base0 = 1;
    for (int i = 0; i < s->k; i++) {
        for (int c = 0; c < 3; c++) {
            double gv = 0;
            for (int j = 0; j < s->k; j++)
                gv += s->ginv[i][j] * e[j][c];
            m->grad[i + 1][c] = gv / (1 - t);
            sum[c] += m->grad[i + 1][c];
        }
        m->base[i + 1] = s->mu_f[i] - s->mu_f[i] / (1 - t); /* mu_i at x = a */
        base0 -= m->base[i + 1];
    }
    m->base[0] = base0;
    for (int c = 0; c < 3; c++)
        m->grad[0][c] = -sum[c];
    for (int i = 0; i <= s->k; i++)
        m->glen[i] = sqrt(dot3(m->grad[i], m->grad[i]));
}

/* 0 only when no point within h of c has z* in X (some mu_i < 0 on the whole ball): x in the
 * mixed cell of X needs z* in X. Keeps the thin prisms of edges and triangles whose power face
 * is long (faces of slivers) out of the cells beside them. */
static int prism_near(const bary_map *m, const double c[3], double h)
{
    double d[3] = {c[0] - m->a[0], c[1] - m->a[1], c[2] - m->a[2]}, dl = sqrt(dot3(d, d));
    for (int i = 0; i <= m->k; i++) {
        double mu = m->base[i] + dot3(m->grad[i], d);
        /* 1e-9 of the terms' sizes: far above the rounding of mu here and in the scan (the
         * Gram condition is <= 1e10 without SKIN_SHAKY_COND) */
        double slack = 1e-9 * (1 + fabs(m->base[i]) + m->glen[i] * (dl + h));
        if (mu < -h * m->glen[i] - slack) return 0;
    }
    return 1;
}

/* Cell centre of cell (x, y, z). */
static void cell_centre(const fl_skin_function *sk, size_t x, size_t y, size_t z, double c[3])
{
    c[0] = sk->origin[0] + ((double)x + 0.5) * sk->cell;
    c[1] = sk->origin[1] + ((double)y + 0.5) * sk->cell;
    c[2] = sk->origin[2] + ((double)z + 0.5) * sk->cell;
}

void skin_index_centre(const fl_skin_function *skin, size_t id, double c[3])
{
    cell_centre(skin, id % skin->dims[0], id / skin->dims[0] % skin->dims[1],
                id / skin->dims[0] / skin->dims[1], c);
}

/* Whether the index lists s at all, with its registration box (reg_box): simplices without a
 * positive ball are never the minimiser of a negative G, and a mixed cell beyond the reach of
 * its simplex only holds G >= 0. */
int skin_listed_box(const fl_skin_function *sk, const skin_simplex *s, double lo[3],
                    double hi[3])
{
    if (!(skin_reach(sk->balls, s, sk->t) > 0)) return 0;
    reg_box(sk->balls, sk->t, s, lo, hi);
    return lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2];
}

/* Registers simplex i in every cell near it (pass 0 counts into cell_start[id + 1], pass 1
 * fills; both return the number of cells) or, pass 2, returns the number of cells of its box. */
static double register_simplex(fl_skin_function *sk, size_t i, int pass)
{
    size_t c0[3], c1[3];
    double lo[3], hi[3];
    const skin_simplex *s = &sk->simplex[i];
    if (!skin_listed_box(sk, s, lo, hi)) return 0;
    simplex_cells(sk, lo, hi, c0, c1);
    if (pass == 2) /* the budget estimate: the box's cells, an upper bound, without the tests */
        return (double)(c1[0] - c0[0] + 1) * (double)(c1[1] - c0[1] + 1) *
               (double)(c1[2] - c0[2] + 1);
    /* a cell holds a point within the reach iff its centre is within reach + half diagonal */
    double reach = skin_reach(sk->balls, s, sk->t);
    double d = (SKIN_REACH_MARGIN * reach + 0.8660254037844387 * sk->cell) * (1 + 1e-9);
    double count = 0, h = 0.8660254037844387 * sk->cell;
    int prism = s->box_exact != SKIN_BOX_VORONOI && s->k > 0 && !(s->shaky & SKIN_SHAKY_COND);
    bary_map bm;
    if (prism) bary_setup(sk, s, &bm);
    for (size_t z = c0[2]; z <= c1[2]; z++)
        for (size_t y = c0[1]; y <= c1[1]; y++)
            for (size_t x = c0[0]; x <= c1[0]; x++) {
                double c[3];
                cell_centre(sk, x, y, z, c);
                if (s->box_exact != SKIN_BOX_VORONOI && !may_be_near(sk->balls, s, c, d))
                    continue;
                if (prism && !prism_near(&bm, c, h)) continue;
                count++;
                size_t id = (z * sk->dims[1] + y) * sk->dims[0] + x;
                if (pass == 0)
                    sk->cell_start[id + 1]++;
                else if (pass == 1)
                    sk->cell_item[sk->cell_start[id]++] = (uint32_t)i;
            }
    return count;
}

static int cmp_double(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return a < b ? -1 : a > b;
}

/* The box of the registration boxes of the simplices with a positive ball, and the median of
 * their longest sides (0 when there is none). */
static fl_status index_box(const fl_skin_function *sk, double lo[3], double hi[3], double *median,
                           fl_error *err)
{
    double *r = fl_alloc_array(sk->simplex_count + 1, sizeof(double));
    if (!r) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    size_t m = 0;
    for (int c = 0; c < 3; c++) {
        lo[c] = HUGE_VAL;
        hi[c] = -HUGE_VAL;
    }
    for (size_t i = 0; i < sk->simplex_count; i++) {
        double slo[3], shi[3];
        if (!skin_listed_box(sk, &sk->simplex[i], slo, shi)) continue;
        double side = 0;
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], slo[c]);
            hi[c] = fmax(hi[c], shi[c]);
            side = fmax(side, shi[c] - slo[c]);
        }
        r[m++] = side;
    }
    qsort(r, m, sizeof(double), cmp_double);
    *median = m ? r[m / 2] : 0;
    free(r);
    if (m == 0)
        for (int c = 0; c < 3; c++)
            lo[c] = hi[c] = 0;
    return FL_OK;
}

/* Two passes over the simplices (count, then fill) into CSR arrays. */
static fl_status build_index(fl_skin_function *sk, fl_error *err)
{
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, median = 0;
    fl_status st = index_box(sk, lo, hi, &median, err);
    if (st) return st;
    /* Registration covers each simplex's box, so any cell size is correct; cells of half the
     * median box keep the candidate lists short, capped at ~2^18 cells
     * (registering a long simplex visits every cell of its box). Long simplices (across a
     * hollow ball set, e.g. a ring) meet many cells: the cells grow until the registrations fit
     * in max(2e7, 64 per simplex), trading memory for longer lists. */
    double vol = 1, ext = 0;
    for (int c = 0; c < 3; c++) {
        sk->origin[c] = lo[c];
        vol *= hi[c] - lo[c];
        ext = fmax(ext, hi[c] - lo[c]);
    }
    /* Balls whose reach is below the ulp of their coordinates (weight 1e-40 at 1e10) have
     * boxes of side 0; when they are the majority the median is 0, and a cell of size 1 with a
     * single cell left the others' centres outside the index (G = inf at a centre; fuzz_skin).
     * Start from a fraction of the index box instead; only when that is 0 too (every box is
     * the same point) does one cell of any size hold everything. */
    double first = fmax(median, cbrt(vol / 262144.0));
    if (!(first > 0)) first = ext / 64;
    double budget = fmax(2e7, 64.0 * (double)sk->simplex_count);
    size_t cells = 1;
    if (!(first > 0)) { /* no listed simplex, or all their boxes are one point */
        sk->cell = 1;
        sk->dims[0] = sk->dims[1] = sk->dims[2] = 1;
    }
    for (double cell = first; first > 0; cell *= 1.5) {
        sk->cell = cell;
        /* A flat box (balls in a plane, one of them tiny: reach 7e-76) gave cells of 1e-26 and
         * 1e27 of them along an axis, beyond size_t (UBSan; found by fuzz/fuzz_skin.c): grow
         * the cells first until there are at most 2^20 (4 times the target above). */
        double many = 1;
        for (int c = 0; c < 3; c++) many *= floor((hi[c] - lo[c]) / cell) + 1;
        if (many > 1048576.0) continue;
        cells = 1;
        for (int c = 0; c < 3; c++) {
            sk->dims[c] = (size_t)((hi[c] - lo[c]) / sk->cell) + 1;
            cells *= sk->dims[c];
        }
        double total = 0;
        for (size_t i = 0; i < sk->simplex_count; i++)
            total += register_simplex(sk, i, 2);
        if (total <= budget || cells == 1) break;
    }
    sk->cell_start = fl_calloc_array(cells + 1, sizeof(size_t));
    if (!sk->cell_start) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    /* the registration boxes in float, rounded outwards, for the scan's per-point test */
    sk->scan_box = fl_alloc_array(6 * sk->simplex_count + 1, sizeof(float));
    if (!sk->scan_box) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    for (size_t i = 0; i < sk->simplex_count; i++) {
        double blo[3], bhi[3];
        float *b = sk->scan_box + 6 * i;
        if (!skin_listed_box(sk, &sk->simplex[i], blo, bhi)) { /* in no list; an empty box */
            for (int c = 0; c < 3; c++) {
                b[c] = HUGE_VALF;
                b[c + 3] = -HUGE_VALF;
            }
            continue;
        }
        for (int c = 0; c < 3; c++) {
            float flo = (float)blo[c], fhi = (float)bhi[c];
            if ((double)flo > blo[c] || !isfinite(flo)) flo = nextafterf(flo, -HUGE_VALF);
            if ((double)fhi < bhi[c] || !isfinite(fhi)) fhi = nextafterf(fhi, HUGE_VALF);
            b[c] = flo;
            b[c + 3] = fhi;
        }
    }
    for (int pass = 0; pass < 2; pass++) {
        for (size_t i = 0; i < sk->simplex_count; i++)
            register_simplex(sk, i, pass);
        if (pass == 0) {
            for (size_t id = 0; id < cells; id++)
                sk->cell_start[id + 1] += sk->cell_start[id];
            sk->cell_item = fl_alloc_array(sk->cell_start[cells] + 1, sizeof(uint32_t));
            if (!sk->cell_item) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
        } else {
            /* the fill advanced each start to the next cell's start: shift back */
            memmove(sk->cell_start + 1, sk->cell_start, cells * sizeof(size_t));
            sk->cell_start[0] = 0;
        }
    }
    return FL_OK;
}

/* first[b] = the first of count records (size bytes, sorted by their ball[4] at offset off)
 * whose smallest ball is >= b, b = 0 .. n. */
static size_t *first_of(const void *base, size_t count, size_t size, size_t off, size_t n)
{
    size_t *first = fl_calloc_array(n + 2, sizeof(size_t));
    if (!first) return NULL;
    for (size_t i = 0; i < count; i++) {
        uint32_t b0 = ((const uint32_t *)((const char *)base + i * size + off))[0];
        if (b0 < n) first[b0 + 1]++;
    }
    for (size_t b = 0; b < n; b++)
        first[b + 1] += first[b];
    first[n + 1] = first[n];
    return first;
}

static fl_status first_ranges(fl_skin_function *sk, fl_error *err)
{
    sk->first_stored = first_of(sk->simplex, sk->simplex_count, sizeof *sk->simplex,
                                offsetof(skin_simplex, ball), sk->ball_count);
    sk->first_dropped = first_of(sk->dropped, sk->dropped_count, sizeof *sk->dropped,
                                 offsetof(skin_light, ball), sk->ball_count);
    if (!sk->first_stored || !sk->first_dropped)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    return FL_OK;
}

static fl_status function_new(const double *xyzw, size_t n, double t, int positive_only,
                              fl_skin_function **out, fl_error *err)
{
    if (!out || (!xyzw && n)) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "skin: NULL argument");
    *out = NULL;
    if (!(t > 0 && t < 1))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "skin: t must lie in (0, 1), got %g", t);
    if (n >= UINT32_MAX / 2) return fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: too many balls");
    double wmax = 0;
    for (size_t i = 0; i < 4 * n; i++)
        if (!isfinite(xyzw[i]) || fabs(xyzw[i]) > 1e100)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "skin: ball %zu has a non-finite or huge coordinate", i / 4);
    for (size_t i = 0; i < n; i++)
        wmax = fmax(wmax, xyzw[4 * i + 3]);
    if (!(wmax > 0))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: no ball has a positive radius");
    fl_skin_function *sk = calloc(1, sizeof *sk);
    if (!sk) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    sk->t = t;
    sk->wmax = wmax;
    fl_vec v, link, link_start, dropped, dlink_start;
    fl_vec_init(&v, sizeof(skin_simplex));
    fl_vec_init(&link, sizeof(uint32_t));
    fl_vec_init(&link_start, sizeof(size_t));
    fl_vec_init(&dropped, sizeof(skin_light));
    fl_vec_init(&dlink_start, sizeof(size_t));
    fl_status st = FL_OK;
    /* the simplices' frames are read from the balls (skin_frame), the walk reads the balls of
     * the link; one word of shared hint (skin_cell.c) */
    sk->balls = fl_alloc_array(4 * n, sizeof(double));
    sk->hint = calloc(1, sizeof *sk->hint);
    if (!sk->balls || !sk->hint) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    } else {
        memcpy(sk->balls, xyzw, 4 * n * sizeof(double));
        atomic_init(sk->hint, 0);
    }
    if (!st && n <= 8) {
        if (subsets(&v, xyzw, n)) st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    } else if (!st) {
        st = rt_simplices(&v, &link, &link_start, &dropped, &dlink_start, xyzw, n, positive_only,
                          err);
        sk->walkable = !st;
    }
    sk->simplex_count = v.count;
    sk->simplex = fl_vec_release(&v);
    sk->link = fl_vec_release(&link);
    sk->link_start = fl_vec_release(&link_start);
    sk->dropped_count = dropped.count;
    sk->dropped = fl_vec_release(&dropped);
    sk->dropped_link_start = fl_vec_release(&dlink_start);
#ifdef FL_SKIN_WALK_STATS
    if (sk->dropped_count)
        fprintf(stderr, "skin function: %zu stored simplices (%zu link entries), %zu dropped "
                "(%zu link entries): %zu extra bytes\n", sk->simplex_count,
                sk->link_start[sk->simplex_count], sk->dropped_count,
                sk->dropped_link_start[sk->dropped_count] - sk->dropped_link_start[0],
                sk->dropped_count * (sizeof(skin_light) + sizeof(size_t)) + sizeof(size_t) +
                    (sk->dropped_link_start[sk->dropped_count] - sk->dropped_link_start[0]) *
                        sizeof(uint32_t));
#endif
    sk->ball_count = n;
    if (!st && sk->walkable) st = first_ranges(sk, err);
    if (!st && !skin_clip_off) st = skin_clip_boxes(sk, SKIN_REACH_MARGIN, err);
    if (!st) st = build_index(sk, err);
    if (!st && sk->walkable) st = skin_seed_cells(sk, err);
    if (st) {
        fl_skin_function_free(sk);
        return st;
    }
    *out = sk;
    return FL_OK;
}

fl_status fl_skin_function_new(const double *xyzw, size_t n, double t, fl_skin_function **out,
                               fl_error *err)
{
    return function_new(xyzw, n, t, 0, out, err);
}

/* The mesher's skin function: only the simplices with a positive ball (skin_internal.h). */
fl_status skin_function_new_mesher(const double *xyzw, size_t n, double t,
                                   fl_skin_function **out, fl_error *err)
{
    return function_new(xyzw, n, t, 1, out, err);
}

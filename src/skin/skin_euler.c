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
 * Exactness. Both decisions are signs of bordered determinants of the simplex's Gram matrix
 * (src/predicates/power.c derives them; the focus f is a + sum eta_i e_i with G eta = s / 2):
 *   - link test of ball b: the sign of det [[G, g], [s^T, s_b]] is that of pi_b(f) - pi_X(f);
 *   - power: the sign of det [[G, s], [s^T, 4 w_0]] is the opposite of pi_X(f)'s.
 * fl_power_bordered_sign evaluates each in floating point with a forward error bound and, when
 * that does not certify the sign, in big integers. Ties (f on a facet of nu_X) are harmless
 * either way: there f is also the focus of the coface and pi_X(f) its value, so both branches
 * give the same answer.
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
#include "predicates/power.h"
#include "skin/skin_internal.h"

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

/* Sign of the bordered determinant of simplex x[0..k] (mode FL_BORDERED_LINK with ball b, or
 * FL_BORDERED_POWER; power.h): the filter, else the exact stage (2: out of memory). */
static int bordered_sign(const double *balls, const uint32_t *x, int k, int mode, uint32_t b)
{
    const double *z[5];
    for (int i = 0; i <= k; i++)
        z[i] = balls + 4 * (size_t)x[i];
    if (mode == FL_BORDERED_LINK) z[k + 1] = balls + 4 * (size_t)b;
    return fl_power_bordered_sign(z, k, mode);
}

/* ---- the dual complex, from tetrahedra down to vertices ---- */

/* X = group[0].v with its cofaces group[0..count-1]: 1 when X is in K, 0 when not, -1 when
 * out of memory. */
static int decide(const double *balls, const simplex_rec *group, size_t count, int k)
{
    for (size_t i = 0; i < count; i++)
        if (group[i].in) return 1; /* nu_Y lies in nu_X, where pi_X = pi_Y < 0 */
    for (size_t i = 0; i < count; i++) {
        int s = bordered_sign(balls, group[0].v, k, FL_BORDERED_LINK, group[i].opp);
        if (s == 2) return -1;
        if (s < 0) return 0; /* f beyond the facet of the coface: the minimum is on the boundary */
    }
    int s = bordered_sign(balls, group[0].v, k, FL_BORDERED_POWER, 0);
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

/* ---- Betti numbers: union-find (core.h) over vertices (b0) and over the complement (b2) ---- */

static uint32_t *uf_new(size_t n)
{
    uint32_t *parent = fl_alloc_array(n ? n : 1, sizeof *parent);
    if (parent)
        for (size_t i = 0; i < n; i++)
            parent[i] = (uint32_t)i;
    return parent;
}

/* b2 = the bounded components of R^3 minus |K|. The complement is the union of the open
 * simplices not in K and the outside of the hull; every simplex not in K has only cofaces not
 * in K, so its points reach the tetrahedra (or the outside) around it without meeting K, and two
 * tetrahedra not in K are in one component iff a path of triangles not in K joins them. So the
 * components are those of the graph on the tetrahedra not in K plus one node for the outside,
 * with an arc per triangle not in K (a hull triangle joins its tetrahedron to the outside).
 * tri[0..tri_count) are the sorted triangles with their `in` flags, tet_in the tetrahedra's.
 * -1 when out of memory. */
static long long complement_cavities(const fl_rt3 *rt, const unsigned char *tet_in,
                                     const simplex_rec *tri, size_t tri_count)
{
    size_t count = rt->tet_count;
    uint32_t *parent = uf_new(count + 1); /* node `count` is the outside */
    if (!parent) return -1;
    for (size_t t = 0; t < count; t++) {
        if (tet_in[t]) continue;
        for (int i = 0; i < 4; i++) {
            uint32_t u = rt->adj[4 * t + i];
            if (u != UINT32_MAX && u < t) continue; /* each inner triangle once */
            simplex_rec key;
            int j = 0;
            for (int c = 0; c < 4; c++)
                if (c != i) key.v[j++] = rt->tet[4 * t + c];
            key.v[3] = UINT32_MAX;
            sort4(key.v);
            const simplex_rec *f = bsearch(&key, tri, tri_count, sizeof *tri, cmp_rec);
            if (f && !f->in)
                fl_uf_union(parent, (uint32_t)t, u == UINT32_MAX ? (uint32_t)count : u);
        }
    }
    long long roots = 0;
    for (size_t t = 0; t <= count; t++)
        roots += (t == count || !tet_in[t]) && fl_uf_find(parent, (uint32_t)t) == t;
    free(parent);
    return roots - 1;
}

/* chi(K) from the tetrahedra of rt over `balls` (auxiliary balls included: they are decided
 * like the others and never come out in K), and with betti non-NULL also b0 and b2 of K into
 * betti[0] and betti[2] (b1 is then b0 + b2 - chi). */
static fl_status dual_euler(const double *balls, const fl_rt3 *rt, long long *chi, long long *betti,
                            fl_error *err)
{
    size_t count = rt->tet_count;
    simplex_rec *level = fl_alloc_array(count ? count : 1, sizeof *level);
    if (!level) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "balls union euler: out of memory");
    unsigned char *tet_in = NULL;
    uint32_t *vertex_parent = NULL;
    if (betti) {
        tet_in = fl_alloc_array(count ? count : 1, 1);
        size_t balls_count = rt->point_count;
        vertex_parent = uf_new(balls_count);
        if (!tet_in || !vertex_parent) goto nomem;
    }
    long long sum = 0;
    /* tetrahedra: nu_X is the point f itself */
    for (size_t t = 0; t < count; t++) {
        memcpy(level[t].v, rt->tet + 4 * t, 4 * sizeof(uint32_t));
        sort4(level[t].v);
        int s = bordered_sign(balls, level[t].v, 3, FL_BORDERED_POWER, 0);
        if (s == 2) goto nomem;
        level[t].in = s > 0;
        sum -= level[t].in;
        if (tet_in) tet_in[t] = (unsigned char)level[t].in;
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
            if (vertex_parent && k == 0) /* the entries of vertex X: its edges X + opp */
                for (size_t g = i; g < j; g++)
                    if (e[g].in) fl_uf_union(vertex_parent, e[g].v[0], e[g].opp);
            memmove(e[count].v, e[i].v, sizeof e[count].v);
            e[count++].in = in;
            if (in) sum += k % 2 ? -1 : 1;
            i = j;
        }
        if (betti && k == 2) {
            betti[2] = complement_cavities(rt, tet_in, e, count);
            if (betti[2] < 0) goto nomem;
        }
    }
    if (betti) {
        betti[0] = 0;
        for (size_t i = 0; i < count; i++) /* level: the vertices with their flags */
            betti[0] += level[i].in && fl_uf_find(vertex_parent, level[i].v[0]) == level[i].v[0];
    }
    free(level);
    free(tet_in);
    free(vertex_parent);
    *chi = sum;
    return FL_OK;
nomem:
    free(level);
    free(tet_in);
    free(vertex_parent);
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

/* chi of the union into *chi, and with betti non-NULL its Betti numbers too (the entry points'
 * checks and zeroing done). */
static fl_status union_topology(const double *xyzw, size_t n, long long *chi, long long *betti,
                                fl_error *err)
{
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
        st = dual_euler(xyzw, &rt, chi, betti, err);
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
        st = dual_euler(all, &rt, chi, betti, err);
        fl_rt3_free(&rt);
    } else if (err) {
        *err = rt_err;
    }
    free(all);
    return st;
}

fl_status fl_balls_union_euler(const double *xyzw, size_t n, long long *chi, fl_error *err)
{
    fl_error_clear(err);
    if (!chi || (n && !xyzw))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "balls union euler: NULL argument");
    *chi = 0;
    return union_topology(xyzw, n, chi, NULL, err);
}

fl_status fl_balls_union_betti(const double *xyzw, size_t n, long long betti[3], fl_error *err)
{
    fl_error_clear(err);
    if (!betti || (n && !xyzw))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "balls union betti: NULL argument");
    betti[0] = betti[1] = betti[2] = 0;
    long long chi = 0;
    fl_status st = union_topology(xyzw, n, &chi, betti, err);
    if (st != FL_OK) {
        betti[0] = betti[1] = betti[2] = 0;
        return st;
    }
    betti[1] = betti[0] + betti[2] - chi;
    return FL_OK;
}

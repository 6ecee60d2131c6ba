/* B_perp (Cheng & Tan §5) and B* (§6.2) from the regular triangulation of the surface balls.
 *
 * B_perp: for every tetrahedron X of the regular triangulation of B, the ball b_X orthogonal to
 * its four balls (centre = the power/Voronoi vertex dual to X) when the centre lies inside the
 * object and the weight is positive (§5 steps 2-4).
 * B*: B_perp plus the orthogonal ball b_X^perp = (z_X^perp, w_X^perp) of every vertex, edge and
 * triangle X whose focus z_X^perp (the point of aff(z_X) with equal power to its balls) lies in
 * its dual power face nu_X with negative power, i.e. the alpha simplices of B with
 * aff(z_X) ∩ nu_X non-empty. The paper also asks conv(z_X) ⊆ O; we keep every such simplex:
 * an extra negative ball cannot move the skin outside ∪B_perp (body^t(B*) ⊆ body^1(B*) =
 * ∪B_perp, §6.1) nor into the interior of ∪B (the proof of Lemma 17 uses only orthogonality,
 * which focus ∈ nu_X gives). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "skin/skin_eps.h"

typedef struct face_entry {
    uint32_t v[3]; /* sorted ball indices, UINT32_MAX padding for vertices and edges */
    uint32_t pass; /* the focus had power <= every other ball of this tetrahedron */
} face_entry;

static int cmp_face(const void *pa, const void *pb)
{
    const face_entry *a = pa, *b = pb;
    for (int i = 0; i < 3; i++)
        if (a->v[i] != b->v[i]) return a->v[i] < b->v[i] ? -1 : 1;
    return 0;
}

static int cmp_ball(const void *pa, const void *pb)
{
    const double *a = pa, *b = pb;
    for (int i = 0; i < 4; i++)
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    return 0;
}

static double power(const double *ball, const double x[3])
{
    double d0 = x[0] - ball[0], d1 = x[1] - ball[1], d2 = x[2] - ball[2];
    return d0 * d0 + d1 * d1 + d2 * d2 - ball[3];
}

/* The focus of the balls s[0..k] (k <= 2) and its power; 0 when aff(z_X) is degenerate. The
 * focus satisfies 2 (z_j - z_0).(f - z_0) = |z_j - z_0|^2 - w_j + w_0 (equal power). */
static int focus(const double *const *s, int k, double f[3], double *pw)
{
    double a[2][3], r[2], g[2][2], mu[2] = {0, 0};
    for (int j = 0; j < k; j++) {
        for (int i = 0; i < 3; i++) a[j][i] = s[j + 1][i] - s[0][i];
        r[j] = 0.5 * (a[j][0] * a[j][0] + a[j][1] * a[j][1] + a[j][2] * a[j][2] - s[j + 1][3] +
                      s[0][3]);
    }
    for (int j = 0; j < k; j++)
        for (int l = 0; l < k; l++)
            g[j][l] = a[j][0] * a[l][0] + a[j][1] * a[l][1] + a[j][2] * a[l][2];
    if (k == 1) {
        if (!(g[0][0] > 0)) return 0;
        mu[0] = r[0] / g[0][0];
    } else if (k == 2) {
        double det = g[0][0] * g[1][1] - g[0][1] * g[1][0];
        if (!(fabs(det) > 1e-14 * g[0][0] * g[1][1])) return 0;
        mu[0] = (r[0] * g[1][1] - r[1] * g[0][1]) / det;
        mu[1] = (g[0][0] * r[1] - g[1][0] * r[0]) / det;
    }
    for (int i = 0; i < 3; i++) {
        f[i] = s[0][i];
        for (int j = 0; j < k; j++) f[i] += mu[j] * a[j][i];
    }
    *pw = power(s[0], f);
    return 1;
}

/* The 14 proper faces of tetrahedron t (4 vertices, 6 edges, 4 triangles), each with whether
 * its focus has power <= that of the tetrahedron's remaining balls (focus ∈ nu_X is decided
 * by the balls of the simplices around X, i.e. by every incident tetrahedron passing). */
static void tet_faces(const double *xyzw, const uint32_t *t, double tol, face_entry *out)
{
    static const int sub[14][3] = {{0, -1, -1}, {1, -1, -1}, {2, -1, -1}, {3, -1, -1},
                                   {0, 1, -1},  {0, 2, -1},  {0, 3, -1},  {1, 2, -1},
                                   {1, 3, -1},  {2, 3, -1},  {0, 1, 2},   {0, 1, 3},
                                   {0, 2, 3},   {1, 2, 3}};
    for (int q = 0; q < 14; q++) {
        uint32_t v[3] = {UINT32_MAX, UINT32_MAX, UINT32_MAX};
        const double *s[3];
        int k = 0, in[4] = {0, 0, 0, 0};
        for (int j = 0; j < 3 && sub[q][j] >= 0; j++, k++) {
            v[k] = t[sub[q][j]];
            in[sub[q][j]] = 1;
        }
        for (int a = 0; a < k; a++) /* sort the (at most 3) indices */
            for (int b = a + 1; b < k; b++)
                if (v[b] < v[a]) {
                    uint32_t x = v[a];
                    v[a] = v[b];
                    v[b] = x;
                }
        for (int j = 0; j < k; j++) s[j] = xyzw + 4 * (size_t)v[j];
        double f[3], pw = 0;
        int pass = focus(s, k - 1, f, &pw);
        for (int c = 0; c < 4 && pass; c++)
            if (!in[c] && power(xyzw + 4 * (size_t)t[c], f) < pw - tol) pass = 0;
        pass = pass && pw < 0;
        memcpy(out[q].v, v, sizeof v);
        out[q].pass = (uint32_t)pass;
    }
}

static fl_status star_faces(const fl_balls *b, const fl_rt3 *rt, double tol, fl_vec *star,
                            fl_error *err)
{
    face_entry *e = fl_alloc_array(rt->tet_count, 14 * sizeof(face_entry));
    if (!e) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (B*)");
    for (size_t i = 0; i < rt->tet_count; i++) tet_faces(b->xyzw, rt->tet + 4 * i, tol, e + 14 * i);
    size_t n = 14 * rt->tet_count;
    qsort(e, n, sizeof *e, cmp_face);
    for (size_t i = 0; i < n;) {
        size_t j = i;
        uint32_t all = 1;
        for (; j < n && !cmp_face(e + i, e + j); j++) all &= e[j].pass;
        if (all) {
            const double *s[3];
            int k = 0;
            while (k < 3 && e[i].v[k] != UINT32_MAX) {
                s[k] = b->xyzw + 4 * (size_t)e[i].v[k];
                k++;
            }
            double ball[4];
            if (focus(s, k - 1, ball, &ball[3]) && fl_vec_push(star, ball, 1)) {
                free(e);
                return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (B*)");
            }
        }
        i = j;
    }
    free(e);
    return FL_OK;
}

/* 1 when the floating-point orthogonal ball o of tetrahedron t is orthogonal to its four balls
 * up to rounding. Symmetric inputs (a cube's protecting balls mirrored across an edge) give
 * slivers whose four centres are coplanar and co-orthogonal up to the last bit of the input:
 * their orthocentre is then decided by rounding noise, and fl_rt3's Cramer solve returned balls
 * of radius 0.9 in the unit cube that are not even orthogonal to their own balls (residual
 * 0.04) and contain other ball centres, against Theorem 4 (docs/skin.md). In exact arithmetic
 * such a degenerate sliver's ball lies on the Voronoi edge dual to the four co-circular balls,
 * and the power to a point along that edge is linear in the position, so the ball is covered
 * by the balls of the edge's two ends: dropping it loses nothing the verification would not
 * catch anyway. */
static int orthogonal_to_tet(const double *xyzw, const uint32_t *t, const double *o)
{
    for (int i = 0; i < 4; i++) {
        const double *z = xyzw + 4 * (size_t)t[i];
        double d2 = (o[0] - z[0]) * (o[0] - z[0]) + (o[1] - z[1]) * (o[1] - z[1]) +
                    (o[2] - z[2]) * (o[2] - z[2]);
        double res = d2 - z[3] - o[3], mag = d2 + fabs(z[3]) + fabs(o[3]);
        if (!(fabs(res) <= 1e-9 * mag)) return 0;
    }
    return 1;
}

/* The ball o orthogonal to the four balls of tetrahedron t, solved in long double relative to
 * the first centre (2 (z_j - z_0).y = |z_j - z_0|^2 - w_j + w_0, y = centre - z_0) by Gaussian
 * elimination with partial pivoting. fl_rt3's ortho (Cramer in doubles on absolute
 * coordinates) was off by up to 0.1 in power on near-flat slivers of symmetric ball sets (the
 * octahedron's Algorithm-1 balls: B_perp balls containing protecting-ball centres). 0 when the
 * system is ill-conditioned (|det| <= 1e-12 of the product of its row lengths): the sliver's
 * orthocentre is then decided by rounding, and as argued at orthogonal_to_tet dropping it
 * loses nothing the verification would not catch. */
static int ortho_ball(const double *xyzw, const uint32_t *t, double o[4])
{
    typedef long double ld;
    const double *z0 = xyzw + 4 * (size_t)t[0];
    ld a[3][4], prod = 1;
    for (int j = 0; j < 3; j++) {
        const double *z = xyzw + 4 * (size_t)t[j + 1];
        ld n2 = 0;
        for (int c = 0; c < 3; c++) {
            a[j][c] = 2 * ((ld)z[c] - z0[c]);
            n2 += a[j][c] * a[j][c];
        }
        a[j][3] = n2 / 4 - (ld)z[3] + z0[3];
        prod *= sqrtl(n2);
    }
    ld det = 1;
    for (int c = 0; c < 3; c++) {
        int piv = c;
        for (int r = c + 1; r < 3; r++)
            if (fabsl(a[r][c]) > fabsl(a[piv][c])) piv = r;
        if (piv != c)
            for (int k = 0; k < 4; k++) {
                ld x = a[c][k];
                a[c][k] = a[piv][k];
                a[piv][k] = x;
            }
        det *= a[c][c];
        if (!(fabsl(det) > 1e-12L * prod) || !isfinite((double)det)) return 0;
        for (int r = c + 1; r < 3; r++) {
            ld f = a[r][c] / a[c][c];
            for (int k = c; k < 4; k++) a[r][k] -= f * a[c][k];
        }
    }
    ld y[3];
    for (int c = 2; c >= 0; c--) {
        ld v = a[c][3];
        for (int k = c + 1; k < 3; k++) v -= a[c][k] * y[k];
        y[c] = v / a[c][c];
    }
    ld d2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
    for (int c = 0; c < 3; c++) o[c] = (double)(z0[c] + y[c]);
    o[3] = (double)(d2 - z0[3]);
    return isfinite(o[0] + o[1] + o[2] + o[3]);
}

/* 1 when o has power >= 0 (to rounding) to the far vertex of each neighbour of tetrahedron i:
 * with the exact regular triangulation every tetrahedron is locally regular, so a computed
 * orthogonal ball closer than orthogonal to a neighbour's ball is a wrong one. */
static int locally_empty(const double *xyzw, const fl_rt3 *rt, size_t i, const double *o)
{
    const uint32_t *t = rt->tet + 4 * i;
    for (int k = 0; k < 4; k++) {
        uint32_t n = rt->adj[4 * i + k];
        if (n >= rt->tet_count) continue;
        for (int j = 0; j < 4; j++) {
            uint32_t v = rt->tet[4 * (size_t)n + j];
            if (v == t[0] || v == t[1] || v == t[2] || v == t[3]) continue;
            const double *z = xyzw + 4 * (size_t)v;
            double d2 = (o[0] - z[0]) * (o[0] - z[0]) + (o[1] - z[1]) * (o[1] - z[1]) +
                        (o[2] - z[2]) * (o[2] - z[2]);
            if (!(d2 - z[3] - o[3] >= -1e-9 * (d2 + fabs(z[3]) + fabs(o[3])))) return 0;
        }
    }
    return 1;
}

/* Sorts the n balls and keeps one of each cluster of balls equal up to rounding; returns the
 * new count. Balls on one orthosphere (a cube's symmetric protecting balls) are triangulated
 * into several tetrahedra sharing one Voronoi vertex, and a rounded symmetric input puts them
 * on spheres that differ by less than their rounding; computed from each tetrahedron, that
 * vertex came out several times, up to 5e-15 apart ("mirror twins": on libcgal-demo cube.off
 * at epsilon 0.5, 489 of 1470 B_perp balls were twins, only exact copies were merged). Keeping
 * one is sound: a ball given twice leaves conv(B), hence the skin, unchanged (§2.1), and two
 * balls closer than SKIN_TWIN_TOL times the extent R (centres; weights in units of R^2) are
 * equal within the rounding each already carries (ortho_ball rounds a long double solve,
 * orthogonal_to_tet accepts residuals of 1e-9); the union moves by no more than that, and the
 * checks downstream (Euler, certified Hausdorff of the union and of the skin mesh) run on the
 * balls kept. */
#define SKIN_TWIN_TOL 1e-12
#define SKIN_TWIN_WINDOW 64
static size_t merge_twins(double *d, size_t n)
{
    if (n < 2) return n;
    qsort(d, n, 4 * sizeof(double), cmp_ball);
    double ext = 0;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            ext = fmax(ext, fabs(d[4 * i + c]) + sqrt(fmax(d[4 * i + 3], 0)));
    double tol = SKIN_TWIN_TOL * ext, wtol = SKIN_TWIN_TOL * ext * ext;
    size_t u = 0;
    for (size_t i = 0; i < n; i++) {
        const double *b = d + 4 * i;
        int twin = 0;
        /* the kept balls are sorted by x: look back while x is within tol, at most
         * SKIN_TWIN_WINDOW balls (many balls sharing one x, e.g. on a symmetry plane, must not
         * make this quadratic; a twin missed only costs the mesher time, never correctness) */
        size_t look = 0;
        for (size_t j = u; j-- > 0 && !twin && look++ < SKIN_TWIN_WINDOW && b[0] - d[4 * j] <= tol;)
            twin = fabs(b[1] - d[4 * j + 1]) <= tol && fabs(b[2] - d[4 * j + 2]) <= tol &&
                   fabs(b[3] - d[4 * j + 3]) <= wtol;
        if (!twin) memmove(d + 4 * u++, b, 4 * sizeof(double));
    }
    return u;
}

fl_status skin_eps_orthogonal_balls(skin_eps_grid *g, const fl_balls *b, fl_balls *perp,
                                    fl_balls *star, fl_error *err)
{
    fl_rt3 rt = {0};
    fl_status st = fl_rt3_build(b->xyzw, b->count, NULL, &rt, err);
    if (st != FL_OK) return st;
    fl_vec vp, vs;
    fl_vec_init(&vp, 4 * sizeof(double));
    fl_vec_init(&vs, 4 * sizeof(double));
    double scale = 0;
    for (size_t i = 0; i < b->count; i++) scale = fmax(scale, b->xyzw[4 * i + 3]);
    for (size_t i = 0; i < rt.tet_count && st == FL_OK; i++) {
        double o[4];
        if (!ortho_ball(b->xyzw, rt.tet + 4 * i, o) || !(o[3] > 0)) continue;
        if (!orthogonal_to_tet(b->xyzw, rt.tet + 4 * i, o)) continue;
        if (!locally_empty(b->xyzw, &rt, i, o)) continue;
        if (skin_eps_inside(g, o) && fl_vec_push(&vp, o, 1))
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (B_perp)");
    }
    if (st == FL_OK) vp.count = merge_twins(vp.data, vp.count);
    if (st == FL_OK && fl_vec_push(&vs, vp.data, vp.count))
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (B*)");
    if (st == FL_OK) st = star_faces(b, &rt, 1e-9 * scale, &vs, err);
    fl_rt3_free(&rt);
    if (st != FL_OK) {
        fl_vec_free(&vp);
        fl_vec_free(&vs);
        return st;
    }
    perp->count = vp.count;
    perp->xyzw = fl_vec_release(&vp);
    star->count = vs.count;
    star->xyzw = fl_vec_release(&vs);
    return FL_OK;
}

/* Algorithm 1 of Cheng & Tan §4.2 (the default placement of the protecting balls B), checked
 * against the statements of the paper by brute force, sharing no code with src/skin:
 *  - C1 (Theorem 5) for pairs: two balls that meet have centres in one closed mesh triangle;
 *  - C2 (left): a ball meeting a triangle, edge or vertex has its centre in it;
 *  - C2 (right, Proposition 10): every vertex, edge and triangle is covered by the balls
 *    (dense sampling: 561 points a triangle, 200 an edge);
 *  - radii: r <= min(0.45 lgs, 0.8 eps) with lgs recomputed by brute force at every centre;
 *  - |K_B| = |P| (Theorem 5, P1 + P2): every simplex of the alpha complex of B (alpha = 0,
 *    from the regular triangulation fl_rt3 and the alpha oracle of skin_oracle.h's method)
 *    lies in one mesh triangle, there is no alpha tetrahedron, and the alpha triangles inside
 *    each mesh triangle have the triangle's area (they tile it) -- cube and tetrahedron only
 *    (O(simplices x balls)); shrinking every ball by 2.5 % makes this check fail on 12 of the
 *    cube's triangles (tried by hand; the 561-point sampling alone missed such thin gaps);
 *  - the whole approximation on a genus-1 torus: verified, Euler 0, Hausdorff <= eps;
 *  - the tetrahedron at eps 0.3 (the subdivision placement failed its Euler check there). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"
#include "skin_cube.h"
#include "skin_oracle.h"
#include "skin/skin_eps.h"

static const double tet_xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
static const uint32_t tet_tri[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

static fl_mesh mesh_of(const double *xyz, size_t nv, const uint32_t *tri, size_t nt)
{
    fl_mesh m = {0};
    m.vertex_count = nv;
    m.triangle_count = nt;
    m.xyz = (double *)xyz;
    m.tri = (uint32_t *)tri;
    return m;
}

/* A torus of radii R = 2, r = 0.75 as an nu x nv grid of quads split in two (outward). */
static fl_mesh torus(int nu, int nv)
{
    fl_mesh m = {0};
    m.vertex_count = (size_t)nu * nv;
    m.triangle_count = 2 * m.vertex_count;
    m.xyz = malloc(3 * m.vertex_count * sizeof(double));
    m.tri = malloc(3 * m.triangle_count * sizeof(uint32_t));
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double u = 2 * 3.14159265358979323846 * i / nu, v = 2 * 3.14159265358979323846 * j / nv,
                   *p = m.xyz + 3 * (i * nv + j);
            p[0] = (2 + 0.75 * cos(v)) * cos(u);
            p[1] = (2 + 0.75 * cos(v)) * sin(u);
            p[2] = 0.75 * sin(v);
        }
    uint32_t *t = m.tri;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            uint32_t a = (uint32_t)(i * nv + j), b = (uint32_t)(((i + 1) % nu) * nv + j),
                     c = (uint32_t)(((i + 1) % nu) * nv + (j + 1) % nv),
                     d = (uint32_t)(i * nv + (j + 1) % nv);
            uint32_t q[6] = {a, b, c, a, c, d};
            memcpy(t, q, sizeof q);
            t += 6;
        }
    return m;
}

/* ---- geometry, long double ---- */

static ld dist_seg(const double *p, const double *a, const double *b)
{
    ld ab[3], ap[3], l2 = 0, s = 0;
    for (int c = 0; c < 3; c++) {
        ab[c] = (ld)b[c] - a[c];
        ap[c] = (ld)p[c] - a[c];
        l2 += ab[c] * ab[c];
        s += ap[c] * ab[c];
    }
    s = l2 > 0 ? s / l2 : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    ld d = 0;
    for (int c = 0; c < 3; c++)
        d += (ap[c] - s * ab[c]) * (ap[c] - s * ab[c]);
    return sqrtl(d);
}

static ld dist_pt(const double *p, const double *a)
{
    ld d = 0;
    for (int c = 0; c < 3; c++)
        d += ((ld)p[c] - a[c]) * ((ld)p[c] - a[c]);
    return sqrtl(d);
}

/* Distance from p to the closed triangle abc. */
static ld dist_tri(const double *p, const double *a, const double *b, const double *c)
{
    ld u[3], v[3], w[3], n[3];
    for (int k = 0; k < 3; k++) {
        u[k] = (ld)b[k] - a[k];
        v[k] = (ld)c[k] - a[k];
        w[k] = (ld)p[k] - a[k];
    }
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    ld nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2],
       h = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]) / nn;
    ld q[3] = {w[0] - h * n[0], w[1] - h * n[1], w[2] - h * n[2]}; /* projection, from a */
    ld s1 = 0, s2 = 0, s3 = 0;
    /* barycentric signs through the cross products with n */
    ld e1[3] = {u[1] * q[2] - u[2] * q[1], u[2] * q[0] - u[0] * q[2], u[0] * q[1] - u[1] * q[0]};
    ld vq[3] = {q[0] - v[0], q[1] - v[1], q[2] - v[2]},
       uv[3] = {v[0] - u[0], v[1] - u[1], v[2] - u[2]};
    ld qu[3] = {q[0] - u[0], q[1] - u[1], q[2] - u[2]};
    ld e2[3] = {uv[1] * qu[2] - uv[2] * qu[1], uv[2] * qu[0] - uv[0] * qu[2],
                uv[0] * qu[1] - uv[1] * qu[0]};
    ld e3[3] = {-v[1] * vq[2] + v[2] * vq[1], -v[2] * vq[0] + v[0] * vq[2],
                -v[0] * vq[1] + v[1] * vq[0]};
    for (int k = 0; k < 3; k++) {
        s1 += e1[k] * n[k];
        s2 += e2[k] * n[k];
        s3 += e3[k] * n[k];
    }
    if (s1 >= 0 && s2 >= 0 && s3 >= 0) return fabsl(h) * sqrtl(nn);
    ld d = dist_seg(p, a, b), d2 = dist_seg(p, b, c), d3 = dist_seg(p, c, a);
    return d < d2 ? (d < d3 ? d : d3) : (d2 < d3 ? d2 : d3);
}

static const double *V(const fl_mesh *m, size_t f, int j)
{
    return m->xyz + 3 * (size_t)m->tri[3 * f + j];
}

/* lgs(p) by brute force: the distance to the nearest vertex, edge or triangle of the mesh not
 * containing p (within tol). */
static ld lgs_brute(const fl_mesh *m, const double *p, ld tol)
{
    ld best = HUGE_VALL;
    for (size_t f = 0; f < m->triangle_count; f++) {
        ld d = dist_tri(p, V(m, f, 0), V(m, f, 1), V(m, f, 2));
        if (d > tol && d < best) best = d;
        for (int j = 0; j < 3; j++) {
            ld de = dist_seg(p, V(m, f, j), V(m, f, (j + 1) % 3)), dv = dist_pt(p, V(m, f, j));
            if (de > tol && de < best) best = de;
            if (dv > tol && dv < best) best = dv;
        }
    }
    return best;
}

/* 1 when p lies in the closed triangle f / segment ab (within tol). */
static int in_tri(const fl_mesh *m, size_t f, const double *p, ld tol)
{
    return dist_tri(p, V(m, f, 0), V(m, f, 1), V(m, f, 2)) <= tol;
}

/* ---- the checks on B ---- */

static skin_eps_sample balls_of(const fl_mesh *m, double eps)
{
    skin_eps_sample s;
    fl_error err;
    CHECK_STATUS(
        skin_eps_surface_balls(m, 0.8 * eps, 0.45, 1000000, FL_SKIN_PLACE_ALGORITHM1, &s, &err),
        FL_OK, &err);
    return s;
}

/* C1 for pairs, C2 (left), the radius rule; returns the number of violations. */
static size_t check_c1_c2_left(const fl_mesh *m, const fl_balls *b, double rmax, const char *name)
{
    size_t bad = 0;
    for (size_t i = 0; i < b->count; i++) {
        const double *p = b->xyzw + 4 * i;
        ld r = sqrtl(p[3]), tol = 1e-9L;
        /* the radius rule of Algorithm 1: r <= min(gamma lgs, rmax), gamma = 0.45 */
        ld lgs = lgs_brute(m, p, 1e-12L);
        if (!(r <= 0.45L * lgs * (1 + 1e-9L) && r <= rmax * (1 + 1e-12))) {
            if (bad++ < 5) fprintf(stderr, "  %s: ball %zu radius %Lg, lgs %Lg\n", name, i, r, lgs);
        }
        for (size_t f = 0; f < m->triangle_count; f++) {
            /* C2 (left): a ball meeting a triangle / edge / vertex has its centre in it */
            if (dist_tri(p, V(m, f, 0), V(m, f, 1), V(m, f, 2)) < r && !in_tri(m, f, p, tol)) {
                if (bad++ < 5) fprintf(stderr, "  %s: ball %zu meets triangle %zu\n", name, i, f);
            }
            for (int j = 0; j < 3; j++) {
                const double *a = V(m, f, j), *c = V(m, f, (j + 1) % 3);
                if (dist_seg(p, a, c) < r && dist_seg(p, a, c) > tol) {
                    if (bad++ < 5) fprintf(stderr, "  %s: ball %zu meets an edge\n", name, i);
                }
                if (dist_pt(p, a) < r && dist_pt(p, a) > tol) {
                    if (bad++ < 5) fprintf(stderr, "  %s: ball %zu holds a vertex\n", name, i);
                }
            }
        }
        /* C1 for pairs: two balls that meet have both centres in one closed triangle */
        for (size_t j = i + 1; j < b->count; j++) {
            const double *q = b->xyzw + 4 * j;
            if (!(dist_pt(p, q) < r + sqrtl(q[3]))) continue;
            int common = 0;
            for (size_t f = 0; f < m->triangle_count && !common; f++)
                common = in_tri(m, f, p, tol) && in_tri(m, f, q, tol);
            if (!common && bad++ < 5)
                fprintf(stderr, "  %s: balls %zu and %zu meet across\n", name, i, j);
        }
    }
    return bad;
}

/* C2 (right): dense samples of every triangle (their edges and corners included) lie in a
 * ball; returns the number of uncovered samples. */
static size_t check_coverage(const fl_mesh *m, const fl_balls *b, const char *name)
{
    enum { N = 32 };
    size_t bad = 0;
    for (size_t f = 0; f < m->triangle_count; f++)
        for (int i = 0; i <= N; i++)
            for (int j = 0; i + j <= N; j++) {
                double x[3];
                for (int c = 0; c < 3; c++)
                    x[c] =
                        (V(m, f, 0)[c] * (N - i - j) + V(m, f, 1)[c] * i + V(m, f, 2)[c] * j) / N;
                int in = 0;
                for (size_t k = 0; k < b->count && !in; k++)
                    in = dist_pt(x, b->xyzw + 4 * k) <= sqrtl(b->xyzw[4 * k + 3]) * (1 + 1e-8L);
                if (!in && bad++ < 5)
                    fprintf(stderr, "  %s: (%g %g %g) of triangle %zu not covered\n", name, x[0],
                            x[1], x[2], f);
            }
    return bad;
}

/* ---- |K_B| = |P| through the alpha complex (alpha = 0) of B ---- */

static ld power_ld(const double *b, const ld *f)
{
    ld d = -(ld)b[3];
    for (int c = 0; c < 3; c++)
        d += (f[c] - b[c]) * (f[c] - b[c]);
    return d;
}

/* The alpha value of every simplex of the regular triangulation (skin_oracle.h's method:
 * w_X when the focus lies in the power cell, else the smallest over the cofaces), then the
 * checks of P1/P2 on the alpha simplices (alpha < 0). Returns the number of violations. */
static size_t check_alpha_complex(const fl_mesh *m, const fl_balls *b, const char *name)
{
    size_t ns = 0, bad = 0;
    oracle_simplex *s = oracle_rt_simplices(b->xyzw, b->count, &ns);
    CHECK(s != NULL);
    if (!s) return 1;
    for (size_t i = 0; i < ns; i++)
        s[i].alpha = HUGE_VALL;
    double *area = calloc(m->triangle_count, sizeof(double));
    for (int k = 3; k >= 0; k--) {
        for (size_t i = 0; i < ns; i++) {
            if (s[i].k != k) continue;
            ld f[3], w;
            if (oracle_focus(b->xyzw, s[i].v, k, f, &w)) continue; /* flat: cofaces decide */
            int in_cell = 1;
            for (size_t j = 0; j < b->count && in_cell; j++) {
                if (j == s[i].v[0] || j == s[i].v[1] || j == s[i].v[2] || j == s[i].v[3]) continue;
                in_cell = !(power_ld(b->xyzw + 4 * j, f) < w);
            }
            if (in_cell && w < s[i].alpha) s[i].alpha = w;
        }
        /* push each (k)-simplex's alpha down to its facets (the cofaces of the next level) */
        for (size_t i = 0; i < ns && k > 0; i++) {
            if (s[i].k != k) continue;
            for (int drop = 0; drop <= k; drop++) {
                oracle_simplex key = {{UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX}, k - 1, 0};
                for (int a = 0, c = 0; a <= k; a++)
                    if (a != drop) key.v[c++] = s[i].v[a];
                oracle_simplex *hit = bsearch(&key, s, ns, sizeof *s, oracle_cmp);
                if (hit && s[i].alpha < hit->alpha) hit->alpha = s[i].alpha;
            }
        }
    }
    /* a facet gets its cofaces' alpha before its own focus test; the minimum of both is its
     * alpha value (the focus value counts only when the focus lies in the cell) */
    for (size_t i = 0; i < ns; i++) {
        if (!(s[i].alpha < 0)) continue;
        if (s[i].k == 3) {
            if (bad++ < 5) fprintf(stderr, "  %s: an alpha tetrahedron\n", name);
            continue;
        }
        size_t host = SIZE_MAX;
        for (size_t f = 0; f < m->triangle_count && host == SIZE_MAX; f++) {
            int all = 1;
            for (int a = 0; a <= s[i].k && all; a++)
                all = in_tri(m, f, b->xyzw + 4 * s[i].v[a], 1e-9L);
            if (all) host = f;
        }
        if (host == SIZE_MAX) {
            if (bad++ < 5)
                fprintf(stderr, "  %s: an alpha %d-simplex off the mesh\n", name, s[i].k);
            continue;
        }
        if (s[i].k == 2) {
            const double *p0 = b->xyzw + 4 * s[i].v[0], *p1 = b->xyzw + 4 * s[i].v[1],
                         *p2 = b->xyzw + 4 * s[i].v[2];
            double u1[3], u2[3];
            for (int c = 0; c < 3; c++) {
                u1[c] = p1[c] - p0[c];
                u2[c] = p2[c] - p0[c];
            }
            double cx = u1[1] * u2[2] - u1[2] * u2[1], cy = u1[2] * u2[0] - u1[0] * u2[2],
                   cz = u1[0] * u2[1] - u1[1] * u2[0];
            area[host] += 0.5 * sqrt(cx * cx + cy * cy + cz * cz);
        }
    }
    for (size_t f = 0; f < m->triangle_count; f++) {
        const double *a = V(m, f, 0), *p1 = V(m, f, 1), *p2 = V(m, f, 2);
        double u1[3], u2[3];
        for (int c = 0; c < 3; c++) {
            u1[c] = p1[c] - a[c];
            u2[c] = p2[c] - a[c];
        }
        double cx = u1[1] * u2[2] - u1[2] * u2[1], cy = u1[2] * u2[0] - u1[0] * u2[2],
               cz = u1[0] * u2[1] - u1[1] * u2[0], full = 0.5 * sqrt(cx * cx + cy * cy + cz * cz);
        if (!(fabs(area[f] - full) <= 1e-9 * full) && bad++ < 5)
            fprintf(stderr, "  %s: alpha triangles in triangle %zu have area %.12g of %.12g\n",
                    name, f, area[f], full);
    }
    free(area);
    free(s);
    return bad;
}

/* alpha: also the alpha-complex check (O(simplices x balls), too slow for the torus's 2736
 * balls under ASan) */
static void check_all(const fl_mesh *m, double eps, int alpha, const char *name)
{
    skin_eps_sample s = balls_of(m, eps);
    CHECK_MSG(check_c1_c2_left(m, &s.balls, 0.8 * eps, name) == 0, "%s eps %g: C1/C2/radius", name,
              eps);
    CHECK_MSG(check_coverage(m, &s.balls, name) == 0, "%s eps %g: coverage (C2)", name, eps);
    if (alpha)
        CHECK_MSG(check_alpha_complex(m, &s.balls, name) == 0, "%s eps %g: |K_B| = |P|", name, eps);
    skin_eps_sample_free(&s);
}

static void test_cube_balls_satisfy_theorem5(void)
{
    fl_mesh m = skin_cube_mesh();
    check_all(&m, 0.5, 1, "cube");
    check_all(&m, 0.25, 1, "cube");
}

static void test_tetrahedron_balls_satisfy_theorem5(void)
{
    fl_mesh m = mesh_of(tet_xyz, 4, tet_tri, 4);
    check_all(&m, 0.5, 1, "tetrahedron");
    check_all(&m, 0.3, 1, "tetrahedron");
}

static void test_coarse_torus_balls_satisfy_theorem5(void)
{
    fl_mesh m = torus(8, 4);
    check_all(&m, 1.0, 0, "torus 8x4");
    free(m.xyz);
    free(m.tri);
}

/* The whole approximation (fl_skin_approx_build checks itself; here the result's claims are
 * re-checked with fl_mesh_check): verified, Euler characteristic of the input, Hausdorff upper
 * bound <= eps. */
static void check_approx(const fl_mesh *m, double eps, long long euler, const char *name)
{
    fl_skin_approx a;
    fl_error err;
    CHECK_STATUS(fl_skin_approx_build(m, eps, NULL, &a, &err), FL_OK, &err);
    CHECK_MSG(a.verified && a.hausdorff[1] <= eps, "%s eps %g: verified %d hausdorff %g euler %lld",
              name, eps, a.verified, a.hausdorff[1], a.euler);
    fl_mesh_report rep;
    fl_mesh_check_options co = {0};
    co.skip_self_intersections = 1;
    CHECK_STATUS(fl_mesh_check(&a.skin, &co, &rep, &err), FL_OK, &err);
    CHECK_MSG(rep.closed && rep.manifold && rep.euler == euler,
              "%s: closed %d manifold %d euler %lld", name, rep.closed, rep.manifold, rep.euler);
    fl_mesh_report_free(&rep);
    fl_skin_approx_free(&a);
}

static void test_tetrahedron_at_eps_0_3_is_verified(void)
{
    fl_mesh m = mesh_of(tet_xyz, 4, tet_tri, 4);
    check_approx(&m, 0.3, 2, "tetrahedron");
}

static void test_torus_is_approximated_with_genus_1(void)
{
    fl_mesh m = torus(8, 4);
    check_approx(&m, 1.0, 0, "torus 8x4");
    free(m.xyz);
    free(m.tri);
}

int main(void)
{
    (void)euler_union_oracle; /* skin_oracle.h's other oracles serve test_skin_mesh */
    (void)skin_oracle_offset;
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_cube_balls_satisfy_theorem5),
        FL_TEST_CASE(test_tetrahedron_balls_satisfy_theorem5),
        FL_TEST_CASE(test_coarse_torus_balls_satisfy_theorem5),
        FL_TEST_CASE(test_tetrahedron_at_eps_0_3_is_verified),
        FL_TEST_CASE(test_torus_is_approximated_with_genus_1),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}

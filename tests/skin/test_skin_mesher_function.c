/* The mesher's skin function (skin_function_new_mesher, src/skin/skin_function.c) keeps only
 * the simplices of the regular triangulation with a positive ball. B* of the
 * eps-approximation is two thirds negative balls, and storing every simplex took ~10 GB on the
 * npm bunny (854378 balls, docs/skin.md). On B*-like sets (a few positive balls among many
 * negative ones, as B* has: negative balls at the foci of the positive balls' faces):
 *  - the mesher's function holds exactly the simplices with a positive ball, counted
 *    independently from fl_rt3_build (skin_oracle.h), and fewer than the full function, which
 *    holds them all;
 *  - its value has the sign of the definition (skin_oracle.h: min over subsets of <= 4 balls,
 *    long double) everywhere, equals it where it is <= 0 and is never below it; where the walk
 *    answers in a dropped cell (simplices of non-positive balls, round 12) it equals the
 *    definition there too (positive values included), and it does answer in some;
 *  - its record is at most 168 bytes (the frame, focus, orthogonal weight, reach and index box
 *    are recomputed from the balls; 360 bytes before, 4.4 GB for the bunny's 1.2e7 simplices),
 *    and the recomputed focus f and weight w are X's orthogonal ball: f in aff(X) and
 *    |f - z_i|^2 - w_i = w for every ball of X (checked in long double);
 *  - fl_skin_mesh (which uses it) gives a closed, manifold mesh with the Euler characteristic
 *    2 chi(union of the balls) (alpha-complex oracle) and vertices on the skin by the
 *    definition. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "fl_test.h"
#include "skin_rng.h"
#include "skin/skin_internal.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "skin_oracle.h"
#pragma GCC diagnostic pop

static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;

static double rnd(void)
{
    return skin_rng_next(&rng_state);
}

/* np positive balls in [0, 3]^3 (radii 0.5..0.9), then nn negative balls (weights
 * -0.06..-0.01) each near the sphere of a random positive ball, as B*'s negative balls sit at
 * the foci of faces of the protecting balls, on the surface. */
static void bstar_like(double *b, int np, int nn)
{
    for (int i = 0; i < np; i++) {
        for (int c = 0; c < 3; c++)
            b[4 * i + c] = 3 * rnd();
        double r = 0.5 + 0.4 * rnd();
        b[4 * i + 3] = r * r;
    }
    for (int i = np; i < np + nn; i++) {
        const double *p = b + 4 * (int)(rnd() * np);
        double u[3], l = 0, s = sqrt(p[3]) * (0.7 + 0.3 * rnd());
        for (int c = 0; c < 3; c++) {
            u[c] = 2 * rnd() - 1;
            l += u[c] * u[c];
        }
        l = sqrt(l) + 1e-3;
        for (int c = 0; c < 3; c++)
            b[4 * i + c] = p[c] + s * u[c] / l;
        b[4 * i + 3] = -0.01 - 0.05 * rnd();
    }
}

static size_t count_positive(const double *b, const oracle_simplex *s, size_t m)
{
    size_t pos = 0;
    for (size_t i = 0; i < m; i++) {
        int p = 0;
        for (int j = 0; j <= s[i].k; j++)
            p |= b[4 * s[i].v[j] + 3] > 0;
        pos += p;
    }
    return pos;
}

static void test_only_positive_simplices_same_sign(void)
{
    enum { NP = 7, NN = 14, Q = 250 };
    static double b[4 * (NP + NN)];
    const int n = NP + NN;
    for (int round = 0; round < 2; round++) {
        bstar_like(b, NP, NN);
        size_t m = 0;
        oracle_simplex *s = oracle_rt_simplices(b, (size_t)n, &m);
        CHECK(s != NULL);
        if (!s) return;
        size_t pos = count_positive(b, s, m);
        free(s);
        fl_skin_function *full = NULL, *g = NULL;
        fl_error err;
        CHECK_STATUS(fl_skin_function_new(b, (size_t)n, 0.5, &full, &err), FL_OK, &err);
        CHECK_STATUS(skin_function_new_mesher(b, (size_t)n, 0.5, &g, &err), FL_OK, &err);
        if (!full || !g) return;
        CHECK_MSG(full->simplex_count == m, "full function: %zu simplices, triangulation %zu",
                  full->simplex_count, m);
        CHECK_MSG(g->simplex_count == pos && pos < m,
                  "mesher function: %zu simplices, %zu of the %zu have a positive ball",
                  g->simplex_count, pos, m);
        int negatives = 0, in_dropped = 0;
        uint32_t start = 0;
        for (int q = 0; q < Q; q++) {
            double x[3]; /* within 1.3 radii of a positive ball: the skin and both sides */
            const double *p = b + 4 * (int)(rnd() * NP);
            for (int c = 0; c < 3; c++)
                x[c] = p[c] + 1.3 * sqrt(p[3]) * (2 * rnd() - 1);
            double got;
            int why = 0;
            skin_locate_why(g, x, &start, &got, &why);
            double want = (double)skin_oracle_value(b, n, 0.5, x);
            double tol = 1e-9 * (1 + fabs(want));
            negatives += want < 0;
            in_dropped += why == SKIN_WHY_DROPPED;
            if (why == SKIN_WHY_DROPPED) /* a cell of non-positive balls: G itself, >= 0 */
                CHECK_MSG(fabs(got - want) <= tol && want >= -tol,
                          "dropped cell at (%.17g, %.17g, %.17g): %.17g, definition %.17g", x[0],
                          x[1], x[2], got, want);
            else if (want <= 0)
                CHECK_MSG(fabs(got - want) <= tol, "G(%.17g, %.17g, %.17g) = %.17g, definition "
                          "%.17g", x[0], x[1], x[2], got, want);
            else
                CHECK_MSG(got >= want - tol && got > 0, "G(%.17g, %.17g, %.17g) = %.17g below "
                          "the definition %.17g", x[0], x[1], x[2], got, want);
        }
        CHECK_MSG(negatives > Q / 20, "%d negative values", negatives);
        /* the walk crosses the dropped cells and answers in some (round 12) */
        CHECK_MSG(in_dropped > 0, "no answer in a dropped cell of %d", Q);
        printf("round %d: %d of %d answers in dropped cells\n", round, in_dropped, Q);
        fl_skin_function_free(full);
        fl_skin_function_free(g);
    }
}

static void test_lean_record_orthogonal_ball(void)
{
    enum { NP = 7, NN = 14 };
    static double b[4 * (NP + NN)];
    const int n = NP + NN;
    CHECK_MSG(sizeof(skin_simplex) <= 168, "skin_simplex is %zu bytes", sizeof(skin_simplex));
    bstar_like(b, NP, NN);
    fl_skin_function *g = NULL;
    fl_error err;
    CHECK_STATUS(skin_function_new_mesher(b, (size_t)n, 0.5, &g, &err), FL_OK, &err);
    if (!g) return;
    size_t bad = 0;
    for (size_t i = 0; i < g->simplex_count; i++) {
        const skin_simplex *s = &g->simplex[i];
        double a[3], e[3][3], f[3];
        skin_frame(g->balls, s, a, e);
        skin_focus(s, a, e, f);
        long double w = skin_weight(g->balls, s, a, f), scale = 1 + fabsl(w);
        for (int j = 0; j <= s->k; j++) { /* orthogonal to every ball of X */
            const double *z = b + 4 * (size_t)s->ball[j];
            long double d2 = 0;
            for (int c = 0; c < 3; c++)
                d2 += ((long double)f[c] - z[c]) * ((long double)f[c] - z[c]);
            scale += d2 + fabs(z[3]);
            if (fabsl(d2 - z[3] - w) > 1e-9L * scale) bad++;
        }
        long double off = 0, n0 = e[0][1] * e[1][2] - e[0][2] * e[1][1];
        long double n1 = e[0][2] * e[1][0] - e[0][0] * e[1][2];
        long double n2 = e[0][0] * e[1][1] - e[0][1] * e[1][0];
        long double u[3] = {f[0] - a[0], f[1] - a[1], f[2] - a[2]};
        if (s->k == 0) off = fabsl(u[0]) + fabsl(u[1]) + fabsl(u[2]);
        if (s->k == 1) /* |u x e_0| */
            off = fabsl(u[1] * e[0][2] - u[2] * e[0][1]) + fabsl(u[2] * e[0][0] - u[0] * e[0][2]) +
                  fabsl(u[0] * e[0][1] - u[1] * e[0][0]);
        if (s->k == 2) off = fabsl(u[0] * n0 + u[1] * n1 + u[2] * n2);
        if (off > 1e-9L * scale * scale) bad++;
    }
    CHECK_MSG(bad == 0, "%zu of %zu simplices: recomputed focus/weight not the orthogonal ball",
              bad, g->simplex_count);
    CHECK(g->simplex_count > 0);
    fl_skin_function_free(g);
}

static void test_mesh_of_bstar_like_set(void)
{
    enum { NP = 8, NN = 14 };
    static double b[4 * (NP + NN)];
    const int n = NP + NN;
    rng_state = 0x1234567887654321ULL;
    bstar_like(b, NP, NN);
    int ok = 0;
    long long want = 2 * euler_union_oracle(b, (size_t)n, &ok);
    CHECK(ok);
    fl_skin_options o = {0};
    o.t = 0.5;
    o.cell = 0.05;
    fl_mesh mesh;
    fl_error err;
    CHECK_STATUS(fl_skin_mesh(b, (size_t)n, &o, &mesh, NULL, &err), FL_OK, &err);
    if (mesh.vertex_count == 0) return;
    fl_mesh_check_options co = {0};
    co.skip_self_intersections = 1;
    fl_mesh_report rep;
    CHECK_STATUS(fl_mesh_check(&mesh, &co, &rep, &err), FL_OK, &err);
    CHECK(rep.closed && rep.manifold && rep.oriented);
    CHECK_MSG(rep.euler == want, "Euler %lld, 2 chi(union) %lld", rep.euler, want);
    fl_mesh_report_free(&rep);
    double worst = 0;
    for (size_t i = 0; i < mesh.vertex_count; i += 499)
        worst = fmax(worst, skin_oracle_offset(b, n, 0.5, mesh.xyz + 3 * i, 1e-5));
    CHECK_MSG(worst <= 1e-9, "vertex %.3g from the skin", worst);
    fl_mesh_free(&mesh);
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_only_positive_simplices_same_sign),
        FL_TEST_CASE(test_lean_record_orthogonal_ball),
        FL_TEST_CASE(test_mesh_of_bstar_like_set),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}

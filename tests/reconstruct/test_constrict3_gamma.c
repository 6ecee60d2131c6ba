/* The γ-indicator of thesis Def. 5.2 against an independent construction: the circumsphere
 * centre solved from the three bisector planes by Cramer's rule, the circumradius of the
 * triangle from r = |ab| |bc| |ca| / (4 area), the sign from the side of the centre. */
#include "fl_test.h"
#include "reconstruct/constrict3_internal.h"

static double det3(const double m[3][3])
{
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

static double dist(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

static double oracle_gamma(const double *a, const double *b, const double *c, const double *l)
{
    const double *q[3] = {b, c, l};
    double m[3][3], rhs[3], ctr[3];
    for (int i = 0; i < 3; i++) {
        rhs[i] = 0;
        for (int k = 0; k < 3; k++) {
            m[i][k] = 2 * (q[i][k] - a[k]);
            rhs[i] += q[i][k] * q[i][k] - a[k] * a[k];
        }
    }
    double d = det3(m);
    for (int j = 0; j < 3; j++) {
        double mj[3][3];
        for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++)
                mj[i][k] = k == j ? rhs[i] : m[i][k];
        ctr[j] = det3(mj) / d;
    }
    double R = dist(ctr, a);
    double ab = dist(a, b), bc = dist(b, c), ca = dist(c, a), s = (ab + bc + ca) / 2;
    double area = sqrt(s * (s - ab) * (s - bc) * (s - ca));
    double r = ab * bc * ca / (4 * area);
    double u[3], v[3], n[3];
    for (int k = 0; k < 3; k++) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
    }
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    double side_l = 0, side_c = 0;
    for (int k = 0; k < 3; k++) {
        side_l += n[k] * (l[k] - a[k]);
        side_c += n[k] * (ctr[k] - a[k]);
    }
    double g = 1 - r / R;
    return side_l * side_c > 0 ? g : -g;
}

static void test_gamma_indicator_matches_circumsphere_construction(void)
{
    unsigned long long seed = 17;
    int compared = 0;
    for (int it = 0; it < 2000; it++) {
        double p[4][3];
        for (int i = 0; i < 4; i++)
            for (int k = 0; k < 3; k++)
                p[i][k] = 2 * fl_test_rand01(&seed) - 1;
        double want = oracle_gamma(p[0], p[1], p[2], p[3]);
        if (!isfinite(want)) continue;
        double got = constrict3_gamma_indicator(p[0], p[1], p[2], p[3]);
        CHECK_NEAR(got, want, 1e-7);
        CHECK(got >= -1 && got <= 1);
        compared++;
    }
    CHECK(compared > 1900);
}

/* Regular tetrahedron: r = e/√3, R = e√6/4, centre inside: γ = 1 - 4/(3√2). */
static void test_gamma_indicator_of_regular_tetrahedron(void)
{
    const double a[] = {1, 1, 1}, b[] = {1, -1, -1}, c[] = {-1, 1, -1}, l[] = {-1, -1, 1};
    double want = 1 - 4 / (3 * sqrt(2.0));
    CHECK_NEAR(constrict3_gamma_indicator(a, b, c, l), want, 1e-15);
    CHECK_NEAR(constrict3_gamma_indicator(a, c, b, l), want, 1e-15); /* orientation-free */
}

/* A vertex just above the triangle's circumcentre: the sphere's centre is far on the other side,
 * γ -> -1 (delete first, §5.3); a vertex far from the triangle in its plane's direction of the
 * circumcircle's outside: γ -> +1. */
static void test_gamma_indicator_limits(void)
{
    const double a[] = {1, 0, 0}, b[] = {-0.5, 0.8660254037844386, 0},
                 c[] = {-0.5, -0.8660254037844386, 0};
    const double near_in[] = {0, 0, 1e-9}, near_out[] = {5, 0, 1e-9};
    CHECK(constrict3_gamma_indicator(a, b, c, near_in) < -0.999999);
    CHECK(constrict3_gamma_indicator(a, b, c, near_out) > 0.999999);
    /* on the axis at height 1: centre at height 0, γ = 0 (R = r) */
    const double apex[] = {0, 0, 1};
    CHECK_NEAR(constrict3_gamma_indicator(a, b, c, apex), 0.0, 1e-15);
}

FL_TEST_MAIN(FL_TEST_CASE(test_gamma_indicator_matches_circumsphere_construction),
             FL_TEST_CASE(test_gamma_indicator_of_regular_tetrahedron),
             FL_TEST_CASE(test_gamma_indicator_limits))

/* Certified Hausdorff distance between the boundary of a union of balls and a mesh
 * (fl_skin_union_hausdorff, docs/skin.md "Certified Hausdorff distance of the union"):
 *  - a closed-form case (one ball inside a cube: the distance is the corner's, 0.8 sqrt 3 - 1)
 *    lies in the certified interval, which is as narrow as the precision asked for;
 *  - on random ball sets and on B_perp of the octahedron's ε-approximation, dense sampling
 *    gives lower bounds of both directed distances (sphere points outside every other ball:
 *    exact distance to the triangles, brute force here; mesh points: their distance to the
 *    union outside it, their largest depth in one ball inside it), and the certified upper
 *    bound is >= them and close to them; for B_perp it is <= ε (Theorem 14 of Cheng & Tan);
 *  - bad input (NULL, negative precision, no positive ball, NaN or huge ball, infinite mesh
 *    vertex, too many pieces) fails with the documented status. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"
#include "skin_cube.h"

static double rnd(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return ((*s >> 8) & 0xffffff) / (double)0x1000000;
}

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double seg_dist(const double *p, const double *a, const double *b)
{
    double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ap[3] = {p[0] - a[0], p[1] - a[1],
                                                                      p[2] - a[2]};
    double l = dot(ab, ab), s = l > 0 ? dot(ap, ab) / l : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    double d[3] = {ap[0] - s * ab[0], ap[1] - s * ab[1], ap[2] - s * ab[2]};
    return sqrt(dot(d, d));
}

/* Distance from p to triangle abc: the plane's when the projection falls inside (three
 * same-sign edge tests), else the nearest edge's. */
static double tri_dist(const double *p, const double *a, const double *b, const double *c)
{
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1],
                                                                      c[2] - a[2]};
    double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    double nn = sqrt(dot(n, n));
    if (nn > 0) {
        const double *v[3] = {a, b, c};
        int pos = 0, neg = 0;
        for (int k = 0; k < 3; k++) {
            const double *u = v[k], *w = v[(k + 1) % 3];
            double e[3] = {w[0] - u[0], w[1] - u[1], w[2] - u[2]},
                   q[3] = {p[0] - u[0], p[1] - u[1], p[2] - u[2]};
            double x[3] = {e[1] * q[2] - e[2] * q[1], e[2] * q[0] - e[0] * q[2],
                           e[0] * q[1] - e[1] * q[0]};
            double s = dot(x, n);
            pos += s >= 0;
            neg += s <= 0;
        }
        if (pos == 3 || neg == 3) {
            double q[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
            return fabs(dot(q, n)) / nn;
        }
    }
    return fmin(seg_dist(p, a, b), fmin(seg_dist(p, b, c), seg_dist(p, c, a)));
}

static double mesh_dist(const fl_mesh *m, const double *p)
{
    double best = HUGE_VAL;
    for (size_t t = 0; t < m->triangle_count; t++) {
        const uint32_t *v = m->tri + 3 * t;
        best = fmin(best, tri_dist(p, m->xyz + 3 * v[0], m->xyz + 3 * v[1], m->xyz + 3 * v[2]));
    }
    return best;
}

/* Sampled lower bounds of the two directed distances, `per` samples per ball and triangle. */
static void sampled(const fl_balls *b, const fl_mesh *m, int per, unsigned seed, double *from_u,
                    double *from_m)
{
    *from_u = *from_m = 0;
    for (size_t i = 0; i < b->count; i++) {
        const double *c = b->xyzw + 4 * i;
        if (!(c[3] > 0)) continue;
        for (int s = 0; s < per; s++) {
            double z = 2 * rnd(&seed) - 1, ph = 6.283185307179586 * rnd(&seed), q = sqrt(1 - z * z);
            double r = sqrt(c[3]);
            double x[3] = {c[0] + r * q * cos(ph), c[1] + r * q * sin(ph), c[2] + r * z};
            int covered = 0;
            for (size_t j = 0; j < b->count && !covered; j++) {
                const double *o = b->xyzw + 4 * j;
                double d[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
                covered = j != i && o[3] > 0 && dot(d, d) < o[3];
            }
            if (!covered) *from_u = fmax(*from_u, mesh_dist(m, x));
        }
    }
    for (size_t t = 0; t < m->triangle_count; t++) {
        const uint32_t *v = m->tri + 3 * t;
        for (int s = 0; s < per; s++) {
            double u = rnd(&seed), w = rnd(&seed);
            if (u + w > 1) {
                u = 1 - u;
                w = 1 - w;
            }
            double y[3];
            for (int k = 0; k < 3; k++)
                y[k] = m->xyz[3 * v[0] + k] + u * (m->xyz[3 * v[1] + k] - m->xyz[3 * v[0] + k]) +
                       w * (m->xyz[3 * v[2] + k] - m->xyz[3 * v[0] + k]);
            double f = HUGE_VAL;
            for (size_t j = 0; j < b->count; j++) {
                const double *o = b->xyzw + 4 * j;
                if (!(o[3] > 0)) continue;
                double d[3] = {y[0] - o[0], y[1] - o[1], y[2] - o[2]};
                f = fmin(f, sqrt(dot(d, d)) - sqrt(o[3]));
            }
            *from_m = fmax(*from_m, fabs(f));
        }
    }
}

static fl_mesh cube(double *xyz, double a)
{
    for (int v = 0; v < 8; v++) {
        xyz[3 * v] = ((v & 1) ^ ((v >> 1) & 1)) ? a : -a;
        xyz[3 * v + 1] = (v & 2) ? a : -a;
        xyz[3 * v + 2] = (v & 4) ? a : -a;
    }
    fl_mesh m = {8, xyz, 12, (uint32_t *)skin_cube_tri};
    return m;
}

static void test_closed_form(void)
{
    double xyz[24], ball[4] = {0, 0, 0, 1};
    fl_mesh m = cube(xyz, 0.8);
    fl_balls b = {1, ball};
    fl_skin_union_hausdorff_options o = {0};
    o.precision = 1e-3;
    fl_skin_union_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_skin_union_hausdorff(&b, &m, &o, &r, &err), FL_OK, &err);
    double truth = 0.8 * sqrt(3.0) - 1; /* the corner; every other point is nearer */
    CHECK_MSG(r.hausdorff[0] <= truth + 1e-12 && truth <= r.hausdorff[1], "[%g, %g] vs %g",
              r.hausdorff[0], r.hausdorff[1], truth);
    CHECK_MSG(r.hausdorff[1] - r.hausdorff[0] <= 1e-3 + 1e-9, "width %g",
              r.hausdorff[1] - r.hausdorff[0]);
    CHECK_NEAR(r.from_mesh[1], truth, 1.1e-3);
    /* from the sphere: 0.2 at the face centres (outside), 0.8 - 1/sqrt 3 at the diagonals */
    CHECK(r.from_union[1] >= 0.8 - 1 / sqrt(3.0) && r.from_union[1] < truth);
    CHECK(r.pieces > 0);
}

static void check_against_sampling(const fl_balls *b, const fl_mesh *m, double precision,
                                   unsigned seed, double *upper)
{
    fl_skin_union_hausdorff_options o = {0};
    o.precision = precision;
    fl_skin_union_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_skin_union_hausdorff(b, m, &o, &r, &err), FL_OK, &err);
    double su, sm;
    sampled(b, m, 400, seed, &su, &sm);
    printf("  sampled %.4f / %.4f, certified from the union [%.4f, %.4f], from the mesh "
           "[%.4f, %.4f], %zu pieces\n",
           su, sm, r.from_union[0], r.from_union[1], r.from_mesh[0], r.from_mesh[1], r.pieces);
    CHECK_MSG(su <= r.from_union[1] && sm <= r.from_mesh[1], "sampled %g %g, bounds %g %g", su,
              sm, r.from_union[1], r.from_mesh[1]);
    CHECK(r.hausdorff[0] <= r.hausdorff[1]);
    /* the bound is close: within the precision of the directed lower bounds it certifies, and
     * those within a few percent of what sampling finds */
    CHECK(r.from_union[1] - r.from_union[0] <= precision * 1.001);
    CHECK_MSG(r.hausdorff[1] <= fmax(su, sm) + 0.1 * fmax(su, sm) + precision,
              "upper %g, sampled %g", r.hausdorff[1], fmax(su, sm));
    *upper = r.hausdorff[1];
}

static void test_random_sets(void)
{
    unsigned seed = 7;
    double xyz[24];
    fl_mesh m = cube(xyz, 1);
    for (int rep = 0; rep < 3; rep++) {
        double ball[4 * 30];
        for (int i = 0; i < 30; i++) {
            for (int k = 0; k < 3; k++) ball[4 * i + k] = 1.6 * rnd(&seed) - 0.8;
            double r = 0.2 + 0.4 * rnd(&seed);
            ball[4 * i + 3] = r * r;
        }
        ball[3] = -1; /* a negative weight is ignored */
        fl_balls b = {30, ball};
        double upper;
        check_against_sampling(&b, &m, 2e-3, 100 + rep, &upper);
    }
}

static void test_octahedron_perp(void)
{
    static const double xyz[] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    static const uint32_t tri[] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                   2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    fl_mesh m = {6, (double *)xyz, 8, (uint32_t *)tri};
    fl_skin_approx ap;
    fl_error err;
    double eps = 0.6;
    CHECK_STATUS(fl_skin_approx_build(&m, eps, NULL, &ap, &err), FL_OK, &err);
    if (ap.perp.count == 0) return;
    double upper = HUGE_VAL;
    check_against_sampling(&ap.perp, &m, eps / 50, 5, &upper);
    CHECK_MSG(upper <= eps, "union of B_perp within %g of the octahedron, eps %g", upper, eps);
    fl_skin_approx_free(&ap);
}

static void test_bad_input(void)
{
    double xyz[24], ball[4] = {0, 0, 0, 1};
    fl_mesh m = cube(xyz, 1);
    fl_balls b = {1, ball};
    fl_skin_union_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_skin_union_hausdorff(NULL, &m, NULL, &r, &err), FL_ERR_USAGE, &err);
    fl_skin_union_hausdorff_options o = {0};
    o.precision = -1;
    CHECK_STATUS(fl_skin_union_hausdorff(&b, &m, &o, &r, &err), FL_ERR_USAGE, &err);
    ball[3] = -1;
    CHECK_STATUS(fl_skin_union_hausdorff(&b, &m, NULL, &r, &err), FL_ERR_INPUT, &err);
    ball[3] = 1;
    ball[0] = NAN;
    CHECK_STATUS(fl_skin_union_hausdorff(&b, &m, NULL, &r, &err), FL_ERR_INPUT, &err);
    ball[0] = 1e150; /* the sphere would reach beyond the range distance queries take */
    CHECK_STATUS(fl_skin_union_hausdorff(&b, &m, NULL, &r, &err), FL_ERR_INPUT, &err);
    ball[0] = 0;
    xyz[0] = INFINITY;
    CHECK_STATUS(fl_skin_union_hausdorff(&b, &m, NULL, &r, &err), FL_ERR_INPUT, &err);
    xyz[0] = -1;
    o.precision = 1e-9;
    o.max_pieces = 1000;
    CHECK_STATUS(fl_skin_union_hausdorff(&b, &m, &o, &r, &err), FL_ERR_ALGORITHM, &err);
}

FL_TEST_MAIN(FL_TEST_CASE(test_closed_form), FL_TEST_CASE(test_random_sets),
             FL_TEST_CASE(test_octahedron_perp), FL_TEST_CASE(test_bad_input))

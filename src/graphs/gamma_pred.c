/* The signs this module decides combinatorics with, adapted to one convention (see
 * gamma_internal.h). They are thin adapters over the exact predicates of src/predicates, so the
 * shared conventions (Shewchuk's: orient3d > 0 when d is below ccw abc; insphere > 0 when e is
 * inside and orient3d(a,b,c,d) > 0) are translated in exactly one place. */
#include "graphs/gamma_internal.h"

int gamma_orient2(const double *a, const double *b, const double *c)
{
    return fl_orient2d(a, b, c);
}

/* (d-a).((b-a)x(c-a)) = det[b-a; c-a; d-a] = -det[a-d; b-d; c-d] = -orient3d. */
int gamma_side3(const double *a, const double *b, const double *c, const double *d)
{
    return -fl_orient3d(a, b, c, d);
}

int gamma_in_circle(const double *a, const double *b, const double *w, const double *e)
{
    return fl_incircle(a, b, w, e) * fl_orient2d(a, b, w);
}

int gamma_in_sphere(const double *a, const double *b, const double *c, const double *w,
                    const double *e)
{
    return fl_insphere(a, b, c, w, e) * fl_orient3d(a, b, c, w);
}

/* ---- exact signs of small sums of products of coordinate differences ----
 * Distance comparisons (Gabriel, relative neighbourhood, lune, nearest neighbour, EMST order)
 * are signs of sum_k coef_k * (x_k - y_k) * (u_k - w_k). Each difference is split exactly into
 * two doubles (Knuth's TwoSum), each product into two (Dekker's TwoProduct with Veltkamp's
 * split; the build disables FMA contraction, so the split is exact), and the terms are summed
 * exactly into a nonoverlapping expansion (Shewchuk's Grow-Expansion), whose largest component
 * has the sign of the sum. Inputs are assumed far from overflow (|x| < 2^500). */

static void two_sum(double a, double b, double *s, double *e)
{
    *s = a + b;
    double bv = *s - a, av = *s - bv;
    *e = (a - av) + (b - bv);
}

static void split(double a, double *hi, double *lo)
{
    double c = 134217729.0 * a; /* 2^27 + 1 */
    double big = c - a;
    *hi = c - big;
    *lo = a - *hi;
}

static void two_product(double a, double b, double *p, double *e)
{
    *p = a * b;
    double ah, al, bh, bl;
    split(a, &ah, &al);
    split(b, &bh, &bl);
    *e = al * bl - (((*p - ah * bh) - al * bh) - ah * bl);
}

/* Adds b into the expansion e[0..*n-1] (increasing magnitude), dropping zeros. */
static void grow(double *e, int *n, double b)
{
    int m = 0;
    double q = b;
    for (int i = 0; i < *n; i++) {
        double s, t;
        two_sum(q, e[i], &s, &t);
        if (t != 0) e[m++] = t;
        q = s;
    }
    if (q != 0) e[m++] = q;
    *n = m;
}

int gamma_exact_sum_sign(int terms, const double *coef, const double *const *x,
                         const double *const *y, const double *const *u, const double *const *w,
                         int dim)
{
    double e[512];
    int n = 0;
    for (int k = 0; k < terms; k++)
        for (int i = 0; i < dim; i++) {
            double d1[2], d2[2];
            two_sum(x[k][i], -y[k][i], &d1[0], &d1[1]);
            two_sum(u[k][i], -w[k][i], &d2[0], &d2[1]);
            for (int a = 0; a < 2; a++)
                for (int b = 0; b < 2; b++) {
                    double p[2];
                    two_product(d1[a], d2[b], &p[0], &p[1]);
                    for (int c = 0; c < 2; c++) {
                        double q[2];
                        two_product(p[c], coef[k], &q[0], &q[1]);
                        grow(e, &n, q[0]);
                        grow(e, &n, q[1]);
                    }
                }
        }
    return n == 0 ? 0 : (e[n - 1] > 0) - (e[n - 1] < 0);
}

int gamma_diametral_sign(const double *a, const double *b, const double *p, int dim)
{
    return fl_diametral(a, b, p, dim);
}

int gamma_compare_dist(const double *a, const double *b, const double *c, const double *d, int dim)
{
    const double coef[2] = {1, -1}, *x[2] = {a, c}, *y[2] = {b, d};
    return gamma_exact_sum_sign(2, coef, x, y, x, y, dim);
}

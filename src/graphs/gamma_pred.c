/* The signs this module decides combinatorics with, adapted to one convention (see
 * gamma_internal.h). They are thin adapters over the exact predicates of src/predicates, so the
 * shared conventions (Shewchuk's: orient3d > 0 when d is below ccw abc; insphere > 0 when e is
 * inside and orient3d(a,b,c,d) > 0) are translated in exactly one place. */
#include "graphs/gamma_internal.h"
#include "predicates/dot_sum.h"

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

/* The same two signs when w's side is already known (gamma_orient2(a, b, w), resp.
 * gamma_side3(a, b, c, w) = -orient3d(a, b, c, w)), saving that predicate. */
int gamma_in_circle_side(const double *a, const double *b, const double *w, int w_side,
                         const double *e)
{
    return fl_incircle(a, b, w, e) * w_side;
}

int gamma_in_sphere_side(const double *a, const double *b, const double *c, const double *w,
                         int w_side, const double *e)
{
    return -fl_insphere(a, b, c, w, e) * w_side;
}

int gamma_exact_sum_sign(int terms, const double *coef, const double *const *x,
                         const double *const *y, const double *const *u, const double *const *w,
                         int dim)
{
    return fl_dot_sum_sign(terms, coef, x, y, u, w, dim);
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

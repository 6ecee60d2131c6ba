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

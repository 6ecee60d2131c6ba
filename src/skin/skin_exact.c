/* Exact sign of a link test of the mixed-cell walk (skin_cell.c): the walk's wrappers around
 * the predicates module's fl_power_link_filter and fl_power_link_exact (src/predicates/power.c,
 * where the determinant, its derivation and its error bound live). They only gather the
 * coordinates of the simplex, the link ball and the query point. */
#include <stddef.h>

#include "predicates/power.h"
#include "skin/skin_internal.h"

/* pts as fl_power_link_filter / fl_power_link_exact take them: the balls of s, the link ball b
 * in the rows beyond s->k, then b and x. */
static void gather(const double *balls, const skin_simplex *s, uint32_t b, const double x[3],
                   const double *pts[5])
{
    const double *zb = balls + 4 * (size_t)b;
    pts[0] = balls + 4 * (size_t)s->ball[0];
    pts[1] = s->k > 0 ? balls + 4 * (size_t)s->ball[1] : zb;
    pts[2] = s->k > 1 ? balls + 4 * (size_t)s->ball[2] : zb;
    pts[3] = zb;
    pts[4] = x;
}

int skin_link_sign_exact(const double *balls, const skin_simplex *s, uint32_t b, const double x[3],
                         double t)
{
    const double *pts[5];
    gather(balls, s, b, x, pts);
    int sg = skin_link_filter_off ? 0 : fl_power_link_filter(pts, s->k, t);
    return sg ? sg : fl_power_link_exact(pts, s->k, t);
}

int skin_link_filter_off;

int skin_link_sign_big(const double *balls, const skin_simplex *s, uint32_t b, const double x[3],
                       double t)
{
    const double *pts[5];
    gather(balls, s, b, x, pts);
    return fl_power_link_exact(pts, s->k, t);
}

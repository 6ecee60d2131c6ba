/* The 2 x 2 solve of the three-split's step 5 (eq. 9.4) on nearly dependent edges.
 *
 * Cramer's rule is forward but not backward stable: its residual |A x - b| can be
 * eps / conditioning times |b|. On CGAL's torus_quad.off five edges have |det A| / |A|_F^2
 * about 3e-8 (nearly, not exactly, dependent: the quadratic boundary curve of surface.c is
 * taken there), and the Cramer residual of 1e-9 |b| left normal jumps of 2.6e-7 to 6.5e-7
 * degrees, above the 1e-7 degree G1 threshold of issue #11. Gaussian elimination with partial
 * pivoting is backward stable (residual eps |A| |x|), and one step of iterative refinement
 * with the residual in long double removes what is left (docs/smooth.md, "Auto"). */
#include <math.h>

#include "smooth/smooth_internal.h"

/* GEPP on the 2 x 2 matrix a in long double; x = 0 when a pivot vanishes (the caller only
 * calls it for |det| > 1e-12 |A|_F^2). */
static void gepp2(const double a[2][2], long double b0, long double b1, long double *x0,
                  long double *x1)
{
    int p = fabs(a[1][0]) > fabs(a[0][0]); /* pivot row */
    long double p0 = a[p][0], p1 = a[p][1], q0 = a[1 - p][0], q1 = a[1 - p][1];
    long double bp = p ? b1 : b0, bq = p ? b0 : b1;
    if (p0 == 0) {
        *x0 = *x1 = 0;
        return;
    }
    long double f = q0 / p0, u = q1 - f * p1;
    *x1 = u != 0 ? (bq - f * bp) / u : 0;
    *x0 = (bp - p1 * *x1) / p0;
}

void g1_solve2_refined(const double a[2][2], long double b0, long double b1, double *x0,
                       double *x1)
{
    long double y0, y1, d0, d1;
    gepp2(a, b0, b1, &y0, &y1);
    long double r0 = b0 - a[0][0] * y0 - a[0][1] * y1, r1 = b1 - a[1][0] * y0 - a[1][1] * y1;
    gepp2(a, r0, r1, &d0, &d1);
    y0 += d0;
    y1 += d1;
    *x0 = isfinite((double)y0) ? (double)y0 : 0;
    *x1 = isfinite((double)y1) ? (double)y1 : 0;
}

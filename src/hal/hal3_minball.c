/* Smallest enclosing ball of the mesh vertices (thesis §7.3.2: the level-0 ball), Welzl's
 * move-to-front algorithm in floating point. Only the choice of v_i, v_j, v_k depends on it;
 * the stored level-0 ball is enlarged afterwards to hold every vertex, so rounding here cannot
 * break containment. */
#include <math.h>
#include <string.h>

#include "hal/hal3_internal.h"

static void ball_of(const double *xyz, const uint32_t *r, int nr, double *b)
{
    if (nr == 0) {
        b[0] = b[1] = b[2] = 0, b[3] = -1; /* empty: every point is outside */
        return;
    }
    const double *p = xyz + 3 * (size_t)r[0];
    b[0] = p[0], b[1] = p[1], b[2] = p[2], b[3] = 0;
    if (nr < 2) return;
    double a[3], c[3], d[3];
    for (int k = 0; k < 3; k++)
        a[k] = xyz[3 * (size_t)r[1] + k] - p[k];
    if (nr == 2) {
        for (int k = 0; k < 3; k++)
            b[k] = p[k] + a[k] / 2;
        b[3] = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) / 4;
        return;
    }
    for (int k = 0; k < 3; k++)
        c[k] = xyz[3 * (size_t)r[2] + k] - p[k];
    double axc[3] = {a[1] * c[2] - a[2] * c[1], a[2] * c[0] - a[0] * c[2],
                     a[0] * c[1] - a[1] * c[0]};
    double la = a[0] * a[0] + a[1] * a[1] + a[2] * a[2],
           lc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    double off[3];
    if (nr == 3) {
        double n2 = axc[0] * axc[0] + axc[1] * axc[1] + axc[2] * axc[2];
        if (!(n2 > 0)) return ball_of(xyz, r, 2, b);
        /* circumcentre in the plane: ((|a|^2 c - |c|^2 a) x (a x c)) / (2 |a x c|^2) */
        double v[3] = {la * c[0] - lc * a[0], la * c[1] - lc * a[1], la * c[2] - lc * a[2]};
        off[0] = (v[1] * axc[2] - v[2] * axc[1]) / (2 * n2);
        off[1] = (v[2] * axc[0] - v[0] * axc[2]) / (2 * n2);
        off[2] = (v[0] * axc[1] - v[1] * axc[0]) / (2 * n2);
    } else {
        for (int k = 0; k < 3; k++)
            d[k] = xyz[3 * (size_t)r[3] + k] - p[k];
        double ld = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        double cxd[3] = {c[1] * d[2] - c[2] * d[1], c[2] * d[0] - c[0] * d[2],
                         c[0] * d[1] - c[1] * d[0]};
        double dxa[3] = {d[1] * a[2] - d[2] * a[1], d[2] * a[0] - d[0] * a[2],
                         d[0] * a[1] - d[1] * a[0]};
        double den = 2 * (a[0] * cxd[0] + a[1] * cxd[1] + a[2] * cxd[2]);
        if (!(fabs(den) > 0)) return ball_of(xyz, r, 3, b);
        for (int k = 0; k < 3; k++)
            off[k] = (la * cxd[k] + lc * dxa[k] + ld * axc[k]) / den;
    }
    for (int k = 0; k < 3; k++)
        b[k] = p[k] + off[k];
    b[3] = off[0] * off[0] + off[1] * off[1] + off[2] * off[2];
}

static int outside(const double *b, const double *x)
{
    return b[3] < 0 || fl_hal3_d2(b, x) > b[3] * (1 + 1e-12);
}

/* Ball of the first n points with the nr points of r on its boundary. */
static void welzl(const double *xyz, size_t n, uint32_t *r, int nr, double *b, uint32_t *sup,
                  int *nsup)
{
    ball_of(xyz, r, nr, b);
    memcpy(sup, r, (size_t)nr * sizeof *r);
    *nsup = nr;
    if (nr == 4) return;
    for (size_t i = 0; i < n; i++) {
        if (!outside(b, xyz + 3 * i)) continue;
        r[nr] = (uint32_t)i;
        welzl(xyz, i, r, nr + 1, b, sup, nsup);
    }
}

void hal3_min_ball(const double *xyz, size_t n, double ball[4], uint32_t sup[4], int *nsup)
{
    uint32_t r[4] = {0, 0, 0, 0};
    welzl(xyz, n, r, 0, ball, sup, nsup);
}

/* The signs this module decides combinatorics with, adapted to one convention (see
 * gamma_internal.h). They are thin adapters over src/predicates so that the conventions of the
 * shared predicates (Shewchuk's: orient3d > 0 when d is below ccw abc; insphere > 0 when e is
 * inside and orient3d(a,b,c,d) > 0) are translated in exactly one place. */
#include "graphs/gamma_internal.h"

/* Until src/predicates lands these are plain floating determinants; they are replaced by the
 * exact fl_orient2d / fl_orient3d / fl_incircle / fl_insphere calls on merge. */
static int sign_of(double x)
{
    return (x > 0) - (x < 0);
}

int gamma_orient2(const double *a, const double *b, const double *c)
{
    double det = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
    return sign_of(det);
}

static double det3(const double *p, const double *q, const double *r)
{
    return p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
           p[2] * (q[0] * r[1] - q[1] * r[0]);
}

int gamma_side3(const double *a, const double *b, const double *c, const double *d)
{
    double u[3], v[3], w[3];
    for (int i = 0; i < 3; i++) {
        u[i] = b[i] - a[i];
        v[i] = c[i] - a[i];
        w[i] = d[i] - a[i];
    }
    return sign_of(det3(u, v, w));
}

int gamma_in_circle(const double *a, const double *b, const double *w, const double *e)
{
    const double *p[3] = {a, b, w};
    double m[3][3];
    for (int i = 0; i < 3; i++) {
        m[i][0] = p[i][0] - e[0];
        m[i][1] = p[i][1] - e[1];
        m[i][2] = m[i][0] * m[i][0] + m[i][1] * m[i][1];
    }
    return sign_of(det3(m[0], m[1], m[2])) * gamma_orient2(a, b, w);
}

int gamma_in_sphere(const double *a, const double *b, const double *c, const double *w,
                    const double *e)
{
    const double *p[4] = {a, b, c, w};
    double m[4][4];
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 3; j++)
            m[i][j] = p[i][j] - e[j];
        m[i][3] = m[i][0] * m[i][0] + m[i][1] * m[i][1] + m[i][2] * m[i][2];
    }
    /* Laplace expansion along the last column. */
    double det = 0;
    for (int i = 0; i < 4; i++) {
        double minor[3][3];
        for (int r = 0, k = 0; r < 4; r++) {
            if (r == i) continue;
            for (int j = 0; j < 3; j++)
                minor[k][j] = m[r][j];
            k++;
        }
        double d = det3(minor[0], minor[1], minor[2]);
        det += ((i + 3) % 2 ? -1.0 : 1.0) * m[i][3] * d;
    }
    /* With (a,b,c,w) positively oriented (det[b-a, c-a, w-a] > 0) this determinant is negative
     * for e inside; the orientation factor makes the sign independent of the vertex order. */
    return -sign_of(det) * gamma_side3(a, b, c, w);
}

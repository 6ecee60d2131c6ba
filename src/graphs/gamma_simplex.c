/* The γ-neighbourhood of one simplex (thesis §3.2-3.3).
 *
 * The balls touching the k vertices of a (k-1)-simplex form a pencil B(t): centre C + t*n,
 * radius sqrt(r^2 + t^2), with C, r the smallest ball and n the unit normal of the simplex's
 * hyperplane H. A point p off H with height h = (p-C).n and power pi = |p-C|^2 - r^2 lies in the
 * open ball B(t) iff pi < 2*t*h, i.e. iff t > tau(p) (h > 0) or t < tau(p) (h < 0), where
 * tau(p) = pi/(2h) is the offset of the ball through the vertices and p. Hence B(t) is empty iff
 * tau(lo) <= t <= tau(up), with `up` the + point of least tau and `lo` the - point of largest
 * tau, and a point p beats the current witness w on its side iff p lies strictly inside the
 * ball through the vertices and w: an exact in-circle / in-sphere test. Which points are the
 * witnesses, whether an empty ball exists, and which points lie on H are therefore decided
 * exactly; only the values c0', c1' are floating constructions from the two witnesses, computed
 * by one function from the same inputs wherever the module needs them.
 *
 * A ball B(t) has |c| = 1 - r/sqrt(r^2 + t^2) (Def. 3.1 solved for c). The largest empty
 * neighbourhood (Def. 3.3) is built from the two extreme balls: the union of B(tau(lo)) and
 * B(tau(up)) when an empty ball exists (c1' >= 0), else the intersection of B(tau(up)) and
 * B(tau(lo)), which is the largest lens that the two witnesses leave empty (c1' < 0). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "graphs/gamma_internal.h"

static double dot(const double *a, const double *b, int dim)
{
    double s = 0;
    for (int i = 0; i < dim; i++)
        s += a[i] * b[i];
    return s;
}

static void cross(const double *a, const double *b, double *out)
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static int frame_init_2d(gamma_frame *f)
{
    const double *a = f->v[0], *b = f->v[1];
    if (a[0] == b[0] && a[1] == b[1]) return 0;
    double d[2] = {b[0] - a[0], b[1] - a[1]};
    double len = hypot(d[0], d[1]);
    f->center[0] = 0.5 * (a[0] + b[0]);
    f->center[1] = 0.5 * (a[1] + b[1]);
    f->r = 0.5 * len;
    /* Left normal: (p-a).n > 0 exactly when orient2d(a,b,p) > 0. */
    f->normal[0] = -d[1] / len;
    f->normal[1] = d[0] / len;
    return 1;
}

/* The axis along which H projects without degeneracy, decided exactly: the projected
 * triangle's orientation is an exact 2D predicate on input coordinates. */
static int projection_axis(const gamma_frame *f)
{
    for (int drop = 2; drop >= 0; drop--) {
        int i = (drop + 1) % 3, j = (drop + 2) % 3;
        double p[3][2];
        for (int k = 0; k < 3; k++) {
            p[k][0] = f->v[k][i];
            p[k][1] = f->v[k][j];
        }
        if (gamma_orient2(p[0], p[1], p[2]) != 0) return drop;
    }
    return -1;
}

/* A point off H, exactly representable: the rounding of v0 + delta*e_axis is whatever double it
 * is, and the exact side test confirms it is off H. */
static int find_aux_point(gamma_frame *f)
{
    for (int axis = 0; axis < 3; axis++) {
        int a = (f->drop + axis) % 3;
        memcpy(f->aux, f->v[0], sizeof f->aux);
        f->aux[a] += fmax(1.0, fabs(f->v[0][a]));
        if (gamma_side3(f->v[0], f->v[1], f->v[2], f->aux) != 0) return 1;
    }
    return 0;
}

static int frame_init_3d(gamma_frame *f)
{
    f->drop = projection_axis(f);
    if (f->drop < 0 || !find_aux_point(f)) return 0;
    double b[3], c[3], n[3], bn[3], cn[3];
    for (int i = 0; i < 3; i++) {
        b[i] = f->v[1][i] - f->v[0][i];
        c[i] = f->v[2][i] - f->v[0][i];
    }
    cross(b, c, n);
    double nn = dot(n, n, 3), bb = dot(b, b, 3), cc = dot(c, c, 3);
    /* Circumcentre: C - a = (|b|^2 (c x n) + |c|^2 (n x b)) / (2 |n|^2). */
    cross(c, n, cn);
    cross(n, b, bn);
    double rel[3];
    for (int i = 0; i < 3; i++) {
        rel[i] = (bb * cn[i] + cc * bn[i]) / (2 * nn);
        f->center[i] = f->v[0][i] + rel[i];
    }
    f->r = sqrt(dot(rel, rel, 3));
    double len = sqrt(nn);
    for (int i = 0; i < 3; i++)
        f->normal[i] = n[i] / len;
    return 1;
}

int gamma_frame_init(gamma_frame *f, const double *coords, int dim, const uint32_t *s)
{
    memset(f, 0, sizeof *f);
    f->dim = dim;
    for (int i = 0; i < dim; i++) {
        f->idx[i] = s[i];
        f->v[i] = coords + (size_t)s[i] * (size_t)dim;
    }
    return dim == 2 ? frame_init_2d(f) : frame_init_3d(f);
}

int gamma_frame_side(const gamma_frame *f, const double *p)
{
    if (f->dim == 2) return gamma_orient2(f->v[0], f->v[1], p);
    return gamma_side3(f->v[0], f->v[1], f->v[2], p);
}

/* +1 when e is strictly inside the ball through the vertices and w (w off H), 0 on it. */
static int in_witness_ball(const gamma_frame *f, const double *w, const double *e)
{
    if (f->dim == 2) return gamma_in_circle(f->v[0], f->v[1], w, e);
    return gamma_in_sphere(f->v[0], f->v[1], f->v[2], w, e);
}

/* A point p on H: inside the closed simplex (vertices excluded: points are distinct) lies in
 * every neighbourhood (the open simplex by Def. 3.1, its relative boundary by §2.2's convention
 * for half-spaces, and strictly inside every finite ball anyway). Otherwise, strictly inside
 * the smallest ball it lies in every finite ball, since B(t) and H meet in the same sphere. */
static void classify_on_plane(gamma_summary *s, const gamma_frame *f, const double *p)
{
    if (f->dim == 2) {
        int axis = f->v[0][0] != f->v[1][0] ? 0 : 1;
        double lo = fmin(f->v[0][axis], f->v[1][axis]), hi = fmax(f->v[0][axis], f->v[1][axis]);
        if (lo < p[axis] && p[axis] < hi) s->blocked_all = 1;
        return;
    }
    int i = (f->drop + 1) % 3, j = (f->drop + 2) % 3;
    double q[2] = {p[i], p[j]}, t[3][2];
    for (int k = 0; k < 3; k++) {
        t[k][0] = f->v[k][i];
        t[k][1] = f->v[k][j];
    }
    int o = gamma_orient2(t[0], t[1], t[2]);
    int inside = 1;
    for (int k = 0; k < 3 && inside; k++)
        if (gamma_orient2(t[k], t[(k + 1) % 3], q) * o < 0) inside = 0;
    if (inside)
        s->blocked_all = 1;
    else if (gamma_in_sphere(f->v[0], f->v[1], f->v[2], f->aux, p) > 0)
        s->blocked_finite = 1;
}

void gamma_summary_init(gamma_summary *s)
{
    s->up = s->lo = GAMMA_NONE;
    s->blocked_all = s->blocked_finite = 0;
}

void gamma_summary_add(gamma_summary *s, const gamma_frame *f, const double *coords, uint32_t i)
{
    for (int k = 0; k < f->dim; k++)
        if (f->idx[k] == i) return;
    const double *p = coords + (size_t)i * (size_t)f->dim;
    int side = gamma_frame_side(f, p);
    if (side == 0) {
        classify_on_plane(s, f, p);
        return;
    }
    uint32_t *w = side > 0 ? &s->up : &s->lo;
    if (*w == GAMMA_NONE) {
        *w = i;
        return;
    }
    /* The witness is on p's side: its side predicate is known. */
    const double *wp = coords + (size_t)*w * (size_t)f->dim;
    int in = f->dim == 2 ? gamma_in_circle_side(f->v[0], f->v[1], wp, side, p)
                         : gamma_in_sphere_side(f->v[0], f->v[1], f->v[2], wp, side, p);
    if (in > 0 || (in == 0 && i < *w)) *w = i;
}

double gamma_frame_offset(const gamma_frame *f, const double *p, int side)
{
    const double *a = f->v[0];
    double d[3] = {0, 0, 0}, ca[3] = {0, 0, 0};
    for (int i = 0; i < f->dim; i++) {
        d[i] = p[i] - a[i];
        ca[i] = f->center[i] - a[i];
    }
    /* pi = |p-C|^2 - |a-C|^2 = |p-a|^2 - 2 (p-a).(C-a), without cancelling two large squares. */
    double pi = dot(d, d, f->dim) - 2 * dot(d, ca, f->dim);
    double h = fabs(dot(d, f->normal, f->dim));
    if (h < DBL_MIN) h = DBL_MIN;
    double tau = pi / (2 * side * h);
    if (f->dim == 2) {
        /* In 2D the sign of pi (w inside the circle with diameter v0v1) is exact, so "which
         * side is the centre on" (c0's sign, Gabriel-ness) is decided exactly. */
        int ps = gamma_diametral_sign(f->v[0], f->v[1], p, 2);
        if (ps == 0) return 0.0;
        tau = fmax(fabs(tau), DBL_TRUE_MIN) * ps * side;
    }
    return tau;
}

/* |c| of the ball B(t): 1 - r/sqrt(r^2+t^2), in a form without cancellation for small t. */
static double ball_magnitude(double t, double r)
{
    if (isinf(t)) return 1.0;
    double q = fabs(t) / r;
    if (isinf(q)) return 1.0;
    double s = hypot(1.0, q);
    return q < 1 ? q * q / (s * (s + 1)) : (s - 1) / s;
}

/* Side of a ball's centre: +1, -1 or 0 (the smallest ball). */
static int offset_side(double t)
{
    return (t > 0) - (t < 0);
}

/* c0' from two extreme balls: magnitude of the smaller ball, sign from whether the centres are
 * on the same side (Def. 3.1: c0*c1 < 0) or opposite sides (c0*c1 > 0) of H. */
static double lesser_parameter(double ta, double tb, double r, int c1_sign)
{
    double ma = ball_magnitude(ta, r), mb = ball_magnitude(tb, r);
    double m = fmax(fmin(ma, mb), DBL_TRUE_MIN); /* nonzero offset: keep the sign */
    int sa = offset_side(ta), sb = offset_side(tb);
    if (sa == 0 || sb == 0) return 0.0;
    int same = sa == sb;
    return same ? -c1_sign * m : c1_sign * m;
}

static void value_with_empty_ball(const gamma_summary *s, double tu, double tl, double r,
                                  gamma_value *out)
{
    out->delaunay = 1;
    if (s->blocked_finite) {
        /* Only the half-spaces can be empty. */
        int up_free = s->up == GAMMA_NONE, lo_free = s->lo == GAMMA_NONE;
        tu = up_free ? INFINITY : -INFINITY;
        tl = lo_free ? -INFINITY : INFINITY;
    }
    out->c1 = fmax(ball_magnitude(tu, r), ball_magnitude(tl, r));
    out->c0 = lesser_parameter(tu, tl, r, +1);
}

static void value_without_empty_ball(const gamma_summary *s, double tu, double tl, double r,
                                     gamma_value *out)
{
    out->delaunay = 0;
    if (!s->blocked_finite) {
        /* The lens B(tu) ∩ B(tl): tu < tl, both witnesses on its boundary. */
        out->c1 = -fmax(ball_magnitude(tu, r), ball_magnitude(tl, r));
        out->c0 = lesser_parameter(tu, tl, r, -1);
    } else {
        /* A point on H inside every finite ball: one ball must be a half-space (c1' = -1),
         * paired with the other side's witness ball; keep the larger c0'. */
        out->c1 = -1.0;
        out->c0 =
            fmax(lesser_parameter(tu, INFINITY, r, -1), lesser_parameter(-INFINITY, tl, r, -1));
    }
    if (out->c1 == 0) out->c1 = -DBL_TRUE_MIN; /* c1' < 0 strictly: decided exactly above */
}

void gamma_summary_value(const gamma_summary *s, const gamma_frame *f, const double *coords,
                         gamma_value *out)
{
    memset(out, 0, sizeof *out);
    if (s->blocked_all) {
        out->never = 1;
        return;
    }
    int has_up = s->up != GAMMA_NONE, has_lo = s->lo != GAMMA_NONE;
    double tu =
        has_up ? gamma_frame_offset(f, coords + (size_t)s->up * (size_t)f->dim, +1) : INFINITY;
    double tl =
        has_lo ? gamma_frame_offset(f, coords + (size_t)s->lo * (size_t)f->dim, -1) : -INFINITY;
    int empty_ball;
    if (!has_up || !has_lo)
        empty_ball = 1;
    else if (s->blocked_finite)
        empty_ball = 0;
    else
        empty_ball = in_witness_ball(f, coords + (size_t)s->up * (size_t)f->dim,
                                     coords + (size_t)s->lo * (size_t)f->dim) <= 0;
    if (empty_ball)
        value_with_empty_ball(s, tu, tl, f->r, out);
    else
        value_without_empty_ball(s, tu, tl, f->r, out);
}

int gamma_value_in_range(const gamma_value *v, const double c[4])
{
    if (v->never) return 0;
    return c[0] <= v->c0 && v->c0 <= c[1] && c[2] <= v->c1 && v->c1 <= c[3];
}

int gamma_value_in_fixed(const gamma_value *v, double c0, double c1)
{
    if (v->never) return 0;
    if (v->c0 >= c0 && v->c1 >= c1) return 1;          /* Lemma 3.1, first term of Lemma 3.2 */
    return c1 < 0 && v->c0 >= c1 && v->c1 >= fabs(c0); /* Lemma 3.2: N(c,-c) = N(-c,c) */
}

int gamma_params_accept(const fl_gamma_params *p, const gamma_value *v)
{
    return p->range ? gamma_value_in_range(v, p->c) : gamma_value_in_fixed(v, p->c[0], p->c[1]);
}

int gamma_simplex_value_all(const double *coords, size_t n, int dim, const uint32_t *s,
                            gamma_value *out)
{
    gamma_frame f;
    if (!gamma_frame_init(&f, coords, dim, s)) {
        memset(out, 0, sizeof *out);
        out->never = 1;
        return 0;
    }
    gamma_summary sum;
    gamma_summary_init(&sum);
    for (size_t i = 0; i < n; i++)
        gamma_summary_add(&sum, &f, coords, (uint32_t)i);
    gamma_summary_value(&sum, &f, coords, out);
    return !out->never;
}

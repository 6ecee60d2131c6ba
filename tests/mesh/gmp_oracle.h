/* An independent exact oracle for segment/triangle intersection: rational coordinates (GMP
 * mpq), intersection points constructed by Cramer's rule and tested by barycentric
 * coordinates. It shares no code or formulation with src/mesh/intersect.c, which decides by
 * orientation signs only. */
#ifndef FL_TEST_GMP_ORACLE_H
#define FL_TEST_GMP_ORACLE_H

#include <gmp.h>

typedef struct q3 {
    mpq_t c[3];
} q3;

static inline void q3_init_d(q3 *v, const double *p, int dim)
{
    for (int k = 0; k < 3; k++) {
        mpq_init(v->c[k]);
        if (k < dim) mpq_set_d(v->c[k], p[k]);
    }
}

static inline void q3_clear(q3 *v)
{
    for (int k = 0; k < 3; k++)
        mpq_clear(v->c[k]);
}

static inline void q3_sub(q3 *r, const q3 *a, const q3 *b)
{
    for (int k = 0; k < 3; k++)
        mpq_sub(r->c[k], a->c[k], b->c[k]);
}

static inline void q_dot(mpq_t r, const q3 *a, const q3 *b)
{
    mpq_t t;
    mpq_init(t);
    mpq_set_ui(r, 0, 1);
    for (int k = 0; k < 3; k++) {
        mpq_mul(t, a->c[k], b->c[k]);
        mpq_add(r, r, t);
    }
    mpq_clear(t);
}

static inline void q3_cross(q3 *r, const q3 *a, const q3 *b)
{
    mpq_t t;
    mpq_init(t);
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        mpq_mul(r->c[k], a->c[i], b->c[j]);
        mpq_mul(t, a->c[j], b->c[i]);
        mpq_sub(r->c[k], r->c[k], t);
    }
    mpq_clear(t);
}

/* 2D cross product of the (i, j) components. */
static inline void q_cross2(mpq_t r, const q3 *a, const q3 *b, int i, int j)
{
    mpq_t t;
    mpq_init(t);
    mpq_mul(r, a->c[i], b->c[j]);
    mpq_mul(t, a->c[j], b->c[i]);
    mpq_sub(r, r, t);
    mpq_clear(t);
}

/* Is x (coplanar with the proper triangle p q r) in the closed triangle? Barycentric
 * coordinates by Cramer's rule in the coordinate plane (i, j) where the triangle is proper. */
static inline int q_point_in_triangle(const q3 *x, const q3 *p, const q3 *q, const q3 *r, int i,
                                      int j)
{
    q3 e1, e2, w;
    mpq_t det, l1, l2;
    for (int k = 0; k < 3; k++)
        mpq_init(e1.c[k]), mpq_init(e2.c[k]), mpq_init(w.c[k]);
    mpq_inits(det, l1, l2, NULL);
    q3_sub(&e1, q, p);
    q3_sub(&e2, r, p);
    q3_sub(&w, x, p);
    q_cross2(det, &e1, &e2, i, j);
    q_cross2(l1, &w, &e2, i, j);
    q_cross2(l2, &e1, &w, i, j);
    mpq_div(l1, l1, det);
    mpq_div(l2, l2, det);
    mpq_add(det, l1, l2);
    int in = mpq_sgn(l1) >= 0 && mpq_sgn(l2) >= 0 && mpq_cmp_ui(det, 1, 1) <= 0;
    mpq_clears(det, l1, l2, NULL);
    q3_clear(&e1), q3_clear(&e2), q3_clear(&w);
    return in;
}

/* Closed segments ab and cd in coordinate plane (i, j): solve a + s(b-a) = c + t(d-c). */
static inline int q_segments_meet2(const q3 *a, const q3 *b, const q3 *c, const q3 *d, int i, int j)
{
    q3 u, v, w;
    mpq_t den, s, t, uu, sc, sd;
    for (int k = 0; k < 3; k++)
        mpq_init(u.c[k]), mpq_init(v.c[k]), mpq_init(w.c[k]);
    mpq_inits(den, s, t, uu, sc, sd, NULL);
    q3_sub(&u, b, a);
    q3_sub(&v, d, c);
    q3_sub(&w, c, a);
    q_cross2(den, &u, &v, i, j);
    int meet;
    if (mpq_sgn(den) != 0) {
        q_cross2(s, &w, &v, i, j);
        q_cross2(t, &w, &u, i, j);
        mpq_div(s, s, den);
        mpq_div(t, t, den);
        meet = mpq_sgn(s) >= 0 && mpq_cmp_ui(s, 1, 1) <= 0 && mpq_sgn(t) >= 0 &&
               mpq_cmp_ui(t, 1, 1) <= 0;
    } else {
        /* parallel: they meet only if collinear and their parameter ranges on ab overlap */
        mpq_mul(uu, u.c[i], u.c[i]);
        mpq_mul(s, u.c[j], u.c[j]);
        mpq_add(uu, uu, s);
        if (mpq_sgn(uu) == 0) { /* ab is a point: is it on cd? swap roles */
            meet = -1;
        } else {
            q_cross2(s, &w, &u, i, j);
            if (mpq_sgn(s) != 0) {
                meet = 0;
            } else {
                mpq_mul(sc, w.c[i], u.c[i]);
                mpq_mul(s, w.c[j], u.c[j]);
                mpq_add(sc, sc, s);
                mpq_div(sc, sc, uu);
                q3_sub(&w, d, a);
                mpq_mul(sd, w.c[i], u.c[i]);
                mpq_mul(s, w.c[j], u.c[j]);
                mpq_add(sd, sd, s);
                mpq_div(sd, sd, uu);
                if (mpq_cmp(sc, sd) > 0) mpq_swap(sc, sd);
                meet = mpq_cmp_ui(sc, 1, 1) <= 0 && mpq_sgn(sd) >= 0;
            }
        }
    }
    mpq_clears(den, s, t, uu, sc, sd, NULL);
    q3_clear(&u), q3_clear(&v), q3_clear(&w);
    if (meet == -1) { /* a == b: point on segment cd iff cd (or the point) contains it */
        if (mpq_equal(c->c[i], d->c[i]) && mpq_equal(c->c[j], d->c[j]))
            return mpq_equal(a->c[i], c->c[i]) && mpq_equal(a->c[j], c->c[j]);
        return q_segments_meet2(c, d, a, a, i, j) == 1;
    }
    return meet;
}

/* The coordinate plane (i, j) dropping the largest normal component. */
static inline void q_plane_axes(const q3 *n, int *i, int *j)
{
    int drop = 0;
    mpq_t a, b;
    mpq_inits(a, b, NULL);
    for (int k = 1; k < 3; k++) {
        mpq_abs(a, n->c[k]);
        mpq_abs(b, n->c[drop]);
        if (mpq_cmp(a, b) > 0) drop = k;
    }
    mpq_clears(a, b, NULL);
    *i = (drop + 1) % 3, *j = (drop + 2) % 3;
}

/* Closed segment ab meets proper closed triangle pqr (3D). */
static inline int q_segment_triangle(const q3 *a, const q3 *b, const q3 *p, const q3 *q,
                                     const q3 *r)
{
    q3 e1, e2, n, w;
    mpq_t da, db, t;
    for (int k = 0; k < 3; k++)
        mpq_init(e1.c[k]), mpq_init(e2.c[k]), mpq_init(n.c[k]), mpq_init(w.c[k]);
    mpq_inits(da, db, t, NULL);
    q3_sub(&e1, q, p);
    q3_sub(&e2, r, p);
    q3_cross(&n, &e1, &e2);
    q3_sub(&w, a, p);
    q_dot(da, &n, &w);
    q3_sub(&w, b, p);
    q_dot(db, &n, &w);
    int i, j, meet;
    q_plane_axes(&n, &i, &j);
    if (mpq_sgn(da) * mpq_sgn(db) > 0) {
        meet = 0;
    } else if (mpq_sgn(da) == 0 && mpq_sgn(db) == 0) {
        meet = q_point_in_triangle(a, p, q, r, i, j) || q_point_in_triangle(b, p, q, r, i, j) ||
               q_segments_meet2(a, b, p, q, i, j) || q_segments_meet2(a, b, q, r, i, j) ||
               q_segments_meet2(a, b, r, p, i, j);
    } else { /* the crossing point x = a + t (b - a), t = da / (da - db) */
        q3 x;
        for (int k = 0; k < 3; k++)
            mpq_init(x.c[k]);
        mpq_sub(t, da, db);
        mpq_div(t, da, t);
        q3_sub(&w, b, a);
        for (int k = 0; k < 3; k++) {
            mpq_mul(x.c[k], w.c[k], t);
            mpq_add(x.c[k], x.c[k], a->c[k]);
        }
        meet = q_point_in_triangle(&x, p, q, r, i, j);
        q3_clear(&x);
    }
    mpq_clears(da, db, t, NULL);
    q3_clear(&e1), q3_clear(&e2), q3_clear(&n), q3_clear(&w);
    return meet;
}

/* Is the triangle proper (nonzero normal)? */
static inline int q_triangle_proper(const double *p, const double *q, const double *r)
{
    q3 P, Q, R, e1, e2, n;
    q3_init_d(&P, p, 3), q3_init_d(&Q, q, 3), q3_init_d(&R, r, 3);
    q3_init_d(&e1, p, 0), q3_init_d(&e2, p, 0), q3_init_d(&n, p, 0);
    q3_sub(&e1, &Q, &P);
    q3_sub(&e2, &R, &P);
    q3_cross(&n, &e1, &e2);
    int proper = mpq_sgn(n.c[0]) || mpq_sgn(n.c[1]) || mpq_sgn(n.c[2]);
    q3_clear(&P), q3_clear(&Q), q3_clear(&R), q3_clear(&e1), q3_clear(&e2), q3_clear(&n);
    return proper;
}

/* Closed segment [a,b] meets the closed proper triangle pqr (double input). */
static inline int oracle_segment_triangle(const double *a, const double *b, const double *p,
                                          const double *q, const double *r)
{
    q3 A, B, P, Q, R;
    q3_init_d(&A, a, 3), q3_init_d(&B, b, 3), q3_init_d(&P, p, 3), q3_init_d(&Q, q, 3);
    q3_init_d(&R, r, 3);
    int m = q_segment_triangle(&A, &B, &P, &Q, &R);
    q3_clear(&A), q3_clear(&B), q3_clear(&P), q3_clear(&Q), q3_clear(&R);
    return m;
}

/* Two closed proper triangles meet iff an edge of one meets the other: their intersection,
 * if not empty, has a boundary point on an edge of one of them, or one contains the other. */
static inline int oracle_triangles(const double *const t1[3], const double *const t2[3])
{
    for (int k = 0; k < 3; k++)
        if (oracle_segment_triangle(t1[k], t1[(k + 1) % 3], t2[0], t2[1], t2[2]) ||
            oracle_segment_triangle(t2[k], t2[(k + 1) % 3], t1[0], t1[1], t1[2]))
            return 1;
    return 0;
}

/* Closed 2D segments (double[2] points). */
static inline int oracle_segments2(const double *a, const double *b, const double *c,
                                   const double *d)
{
    q3 A, B, C, D;
    q3_init_d(&A, a, 2), q3_init_d(&B, b, 2), q3_init_d(&C, c, 2), q3_init_d(&D, d, 2);
    int m = q_segments_meet2(&A, &B, &C, &D, 0, 1);
    q3_clear(&A), q3_clear(&B), q3_clear(&C), q3_clear(&D);
    return m;
}

#endif /* FL_TEST_GMP_ORACLE_H */

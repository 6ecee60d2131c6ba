/* Helpers shared by the files of src/smooth; not part of the public API. */
#ifndef FL_SMOOTH_INTERNAL_H
#define FL_SMOOTH_INTERNAL_H

#include <math.h>

#include "core/core.h"

static inline void g1_sub(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}

static inline double g1_dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void g1_cross(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

/* Scales v to unit length; returns its former length. */
/* |v| without overflow or underflow of |v|^2 (components of 1e-150 or 1e150 are in range). */
static inline double g1_length(const double *v)
{
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (!(m > 0) || isinf(m)) return m;
    double s[3] = {v[0] / m, v[1] / m, v[2] / m};
    return m * sqrt(g1_dot(s, s));
}

static inline double g1_normalize(double *v)
{
    /* Divide by the largest component first: |v|^2 overflowed to inf for components beyond
     * ~1e154 and "normalized" v to the zero vector while reporting success (found by
     * fuzz/fuzz_smooth.c on a mesh at 1e306). Returns |v| (inf when it overflows), 0 for the
     * zero vector and NaN for a non-finite v, which is left unchanged. */
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (!(m > 0) || isinf(m)) return m == 0 ? 0 : NAN;
    double s[3] = {v[0] / m, v[1] / m, v[2] / m}, n = sqrt(g1_dot(s, s));
    v[0] = s[0] / n;
    v[1] = s[1] / n;
    v[2] = s[2] / n;
    return n * m;
}

/* Half-edge 3t+k runs from tri[3t+k] to tri[3t+(k+1)%3]; opp[h] is the half-edge running the
 * other way. Requires a closed, manifold, oriented mesh (checked by the caller). */
fl_status g1_opposite_half_edges(const fl_mesh *mesh, uint32_t **opp, fl_error *err);

/* Fails with FL_ERR_INPUT unless the mesh is closed, manifold and oriented, naming the fault. */
fl_status g1_require_closed_mesh(const fl_mesh *mesh, fl_error *err);

/* Alters the normals of vertices whose star does not project one-to-one on the tangent plane
 * (the orientation condition of §9.6, see normals.c); counts the repairs and the failures. */
fl_status g1_repair_normals(const fl_mesh *mesh, double *normals, size_t *repairs, size_t *failures,
                            fl_error *err);

/* Step 2 (§9.6): q projected on the tangent plane (p, n), a fraction `tension` of the way. */
void g1_edge_point(const double *p, const double *n, const double *q, double tension,
                   double *out);

/* (e, f, g) with e d + f l + g r = 0 for d, l, r in the plane with normal n, scaled to
 * f + g = -1; 0 when f + g = 0 (l and r on one side of d). See surface.c. */
int g1_edge_coefficients(const double *d, const double *l, const double *r, const double *n,
                         double *e, double *f, double *g);

/* The six-split of §9.8 (six_split.c) over a checked mesh with final vertex normals: fills
 * every patch of s (allocated for 6 patches a triangle) and s->singular_edges. */
fl_status g1_six_split(const fl_mesh *m, const double *normals, double tension, fl_g1_surface *s,
                       fl_error *err);

#endif /* FL_SMOOTH_INTERNAL_H */

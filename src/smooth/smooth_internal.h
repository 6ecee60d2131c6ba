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

/* Multiplies v by 2^-k, 2^k the power of two just above its largest |component| (exact unless
 * a component becomes subnormal); leaves zero and non-finite vectors unchanged. */
static inline void g1_pow2_scale(double *v)
{
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (!(m > 0) || isinf(m)) return;
    int k;
    frexp(m, &k);
    for (int d = 0; d < 3; d++)
        v[d] = ldexp(v[d], -k);
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

/* Step 2 (§9.6): the edge point p + tension * tan, tan = the edge from p projected on the
 * tangent plane at p (g1_edge_tangents). */
void g1_edge_point(const double *p, const double *tan, double tension, double *out);

/* The tangent of every half-edge at its start vertex (3 doubles a half-edge): the edge
 * projected on the vertex's tangent plane, rotated within the plane at the vertices whose star
 * projects onto a corner below 1e-3 rad, and with lengths blended towards their mean where a
 * micro corner would have a sine below 1e-3, if spread_corners (tangents.c; *spread counts
 * them). */
fl_status g1_edge_tangents(const fl_mesh *m, const double *normals, const uint32_t *opp,
                           int spread_corners, double *tan, size_t *spread, fl_error *err);

/* (e, f, g) with e d + f l + g r = 0 for d, l, r in the plane with normal n, scaled to
 * f + g = -1; 0 when f + g = 0 (l and r on one side of d). See surface.c. */
int g1_edge_coefficients(const double *d, const double *l, const double *r, const double *n,
                         double *e, double *f, double *g);

/* x with a x = b for a 2 x 2 matrix a that is not singular: partial pivoting in long double
 * and one step of iterative refinement (small_solve.c; the step-5 solve of the three-split on
 * nearly dependent edges). Non-finite results become 0. */
void g1_solve2_refined(const double a[2][2], long double b0, long double b1, double *x0,
                       double *x1);

/* The blossom (polar form) of a cubic Bézier triangle (control points in fl_g1_surface order)
 * at barycentric u1, u2, u3 (six_split.c). */
void g1_blossom(const double net[10][3], const double *u1, const double *u2, const double *u3,
                double *out);

/* Position of b_ijk (k = 3 - i - j) in a cubic net in fl_g1_surface order. */
static inline int g1_ix(int i, int j)
{
    return (3 - i) * (4 - i) / 2 + (3 - i - j);
}

/* The two inner control points of the boundary curve along half-edge h: p[0] next to its
 * start, p[1] next to its end. */
typedef struct edge_ctrl {
    double p[2][3];
} edge_ctrl;

/* One macro triangle's control points before and during the three-split (Figure 9.4 naming):
 * e[k][0], e[k][1] the edge points of edge k (from vertex k to k+1) near vertex k and k+1,
 * c111 the centre (step 3), w[k] the points of the micro edge (vertex k, split point) next to
 * the vertex (step 4), x[k] the inner point of the micro patch on edge k (step 5). */
typedef struct macro_net {
    double e[3][2][3];
    double c111[3];
    double w[3][3];
    double x[3][3];
} macro_net;

/* The macro patch of triangle t (steps 1-3) as 10 control points (surface.c). */
void g1_macro_ctrl(const fl_mesh *m, size_t t, const macro_net *net, double ctrl[10][3]);

/* The two-split of §9.7 (two_split.c) on top of solved three-split nets: picks pairs of thin
 * triangles (paired[t] = partner or UINT32_MAX), writes their four micro patches each to
 * s->ctrl from patch index 0 on (*patches = how many) and re-solves, per eq. 9.7, the inner
 * point x of every three-split neighbour on the edges it shares with a pair. */
fl_status g1_two_split(const fl_mesh *m, const double *normals, const uint32_t *opp,
                       macro_net *nets, fl_g1_surface *s, uint32_t *paired, size_t *patches,
                       fl_error *err);

/* Pairs of thin triangles (two_split.c): pair_edge[t] = the half-edge of t shared with its
 * partner, UINT32_MAX for a three-split triangle. No two pairs are adjacent. */
fl_status g1_choose_pairs(const fl_mesh *m, const uint32_t *opp, uint32_t *pair_edge,
                          fl_error *err);

/* The G1 two-split (cross split): sets the w of both triangles of every pair to the C1 spoke
 * points of the quad, before the outer edges are solved by eq. 9.4. */
void g1_pair_spoke_points(const uint32_t *opp, const uint32_t *pair_edge, size_t nt,
                          macro_net *nets);

/* Writes the four patches of the pair split across half-edge h from patch p on (their inner
 * points x solved on the outer edges); returns the next free patch index. */
size_t g1_emit_cross_split(const fl_mesh *m, const uint32_t *opp, uint32_t h,
                           const macro_net *nets, fl_g1_surface *s, size_t p);

/* The six-split of §9.8 (six_split.c) over a checked mesh with final vertex normals: fills
 * every patch of s (allocated for 6 patches a triangle) and s->singular_edges. */
fl_status g1_six_split(const fl_mesh *m, const double *normals, const double *tan,
                       double tension, fl_g1_surface *s, fl_error *err);

/* Moves the two control points next to every patch corner at a mesh vertex by a few ulps
 * onto the vertex's tangent plane (snap.c): the patch normal there is then the vertex normal
 * to ~1e-3 of an ulp's tilt instead of one rounding. Shared points stay bit-identical. */
void g1_snap_corner_points(fl_g1_surface *s);

/* fl_g1_surface_build after the mesh check (surface.c); o->scheme may be FL_G1_AUTO. */
fl_status g1_build_checked(const fl_mesh *m, const fl_g1_surface_options *o, fl_g1_surface *s,
                          fl_error *err);

/* FL_G1_AUTO (auto_scheme.c): per connected component the three-split where it measures G1,
 * else the six-split (whichever measures better when neither does). */
fl_status g1_auto_build(const fl_mesh *m, const fl_g1_surface_options *o, fl_g1_surface *s,
                        fl_error *err);

/* The edge part of fl_g1_surface_measure (measure.c): max normal jump and folds along every
 * shared patch edge at samples + 1 points; adds to m. */
fl_status g1_measure_edges(const fl_g1_surface *sf, unsigned samples, fl_g1_metrics *m,
                          fl_error *err);

/* The vertex part of fl_g1_surface_measure (measure.c): interpolation errors at the corners
 * that are mesh vertices; max'ed into m. */
void g1_measure_vertices(const fl_g1_surface *sf, const fl_mesh *mesh, fl_g1_metrics *m);

/* The deviation part of fl_g1_surface_measure (measure.c): max distance of a grid of `samples`
 * segments an edge on every patch from the mesh (exact closest points), in mean edge lengths,
 * into m->max_deviation. */
fl_status g1_measure_deviation(const fl_g1_surface *sf, const fl_mesh *mesh, unsigned samples,
                               fl_g1_metrics *m, fl_error *err);

#endif /* FL_SMOOTH_INTERNAL_H */

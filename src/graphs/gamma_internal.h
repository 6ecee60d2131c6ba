/* Internal interface of the graphs module: the γ-neighbourhood of one simplex (thesis §3.2,
 * Def. 3.1), its largest empty neighbourhood parameters (Def. 3.3), and the exact predicates
 * they are decided with. Not part of the public API. */
#ifndef FL_GAMMA_INTERNAL_H
#define FL_GAMMA_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"
#include "core/core.h"

#define GAMMA_NONE UINT32_MAX

/* Exact signs through src/predicates, in one place so every decision of this module uses the
 * same conventions: orient2 > 0 iff abc is counter-clockwise; side3 > 0 iff d lies on the side
 * of plane abc that (b-a)x(c-a) points to; in_ball > 0 iff e lies strictly inside the circle
 * (2D: a,b,w) or sphere (3D: a,b,c,w) through the given points, whatever their orientation. */
int gamma_orient2(const double *a, const double *b, const double *c);
int gamma_side3(const double *a, const double *b, const double *c, const double *d);
int gamma_in_circle(const double *a, const double *b, const double *w, const double *e);
int gamma_in_sphere(const double *a, const double *b, const double *c, const double *w,
                    const double *e);
/* The same when w's side (gamma_orient2(a, b, w), resp. gamma_side3(a, b, c, w); not 0) is
 * known: one predicate instead of two. */
int gamma_in_circle_side(const double *a, const double *b, const double *w, int w_side,
                         const double *e);
int gamma_in_sphere_side(const double *a, const double *b, const double *c, const double *w,
                         int w_side, const double *e);

/* Exact sign of sum_k coef[k] * (x[k]-y[k]).(u[k]-w[k]) over dim coordinates (fl_dot_sum_sign). */
int gamma_exact_sum_sign(int terms, const double *coef, const double *const *x,
                         const double *const *y, const double *const *u, const double *const *w,
                         int dim);
/* Sign of (p-a).(p-b): -1 iff p is strictly inside the ball with diameter ab (Def. 2.9). */
int gamma_diametral_sign(const double *a, const double *b, const double *p, int dim);
/* Sign of |a-b|^2 - |c-d|^2. */
int gamma_compare_dist(const double *a, const double *b, const double *c, const double *d, int dim);

/* A (k-1)-simplex of k vertices in kD with the floating frame its balls are built on: the
 * centre `center` and radius `r` of the smallest ball touching the vertices, and the unit
 * normal `normal` of their hyperplane H. The balls touching the vertices are B(t), centred at
 * center + t*normal, radius sqrt(r^2 + t^2) (t = +-inf: the open half-spaces of H). */
typedef struct gamma_frame {
    int dim;
    uint32_t idx[3];
    const double *v[3];
    double center[3], normal[3], r;
    double aux[3]; /* 3D: a point off H, to test coplanar points against the circumcircle */
    int drop;      /* 3D: the axis dropped to project H without degeneracy */
} gamma_frame;

/* Sets up the frame of the simplex `s` (dim indices into coords). Returns 0 when its vertices
 * coincide or (3D) are collinear: such a simplex has no γ-neighbourhood (Def. 3.1). */
int gamma_frame_init(gamma_frame *f, const double *coords, int dim, const uint32_t *s);

/* Exact side of p with respect to H: +1 on the normal's side, -1 opposite, 0 on H. */
int gamma_frame_side(const gamma_frame *f, const double *p);

/* tau(p): the centre offset of the ball through the vertices and p, for p off H on side `side`
 * (the exact side). Floating construction; in 2D its sign is exact. */
double gamma_frame_offset(const gamma_frame *f, const double *p, int side);

/* What the other points tell about the simplex's balls (thesis §3.3). Over the points added:
 * `up` is the point on the + side whose ball B(tau) has the smallest centre offset tau (no other
 * + point strictly inside its ball), `lo` the point on the - side with the largest tau; ties go
 * to the smallest index. The empty balls are exactly B(t), tau(lo) <= t <= tau(up). A point on
 * H inside the closed simplex lies in every neighbourhood (`blocked_all`); a point on H strictly
 * inside the smallest ball lies in every finite ball (`blocked_finite`). */
typedef struct gamma_summary {
    uint32_t up, lo;
    int blocked_all, blocked_finite;
} gamma_summary;

void gamma_summary_init(gamma_summary *s);
void gamma_summary_add(gamma_summary *s, const gamma_frame *f, const double *coords, uint32_t i);

/* The largest empty neighbourhood N_γ(c0', c1') of a simplex (Def. 3.3). `never` is set when
 * every neighbourhood holds a point; `delaunay` (decided exactly) when some ball touching the
 * vertices is empty, which is when c1' >= 0; otherwise c1' < 0 strictly. */
typedef struct gamma_value {
    int never, delaunay;
    double c0, c1;
} gamma_value;

void gamma_summary_value(const gamma_summary *s, const gamma_frame *f, const double *coords,
                         gamma_value *out);

/* Membership from (c0', c1'): in γ([c0,c1],[c2,c3]) (Def. 3.3), and in γ(c0,c1) through
 * Lemmas 3.1 (c1 >= 0) and 3.2 (c1 < 0). */
int gamma_value_in_range(const gamma_value *v, const double c[4]);
int gamma_value_in_fixed(const gamma_value *v, double c0, double c1);
int gamma_params_accept(const fl_gamma_params *p, const gamma_value *v);

/* The summary of simplex s against all n points (the Theorem 3.1 brute force for one simplex). */
int gamma_simplex_value_all(const double *coords, size_t n, int dim, const uint32_t *s,
                            gamma_value *out);

/* ---- building a graph ---- */

/* One simplex of a graph under construction, vertices sorted increasingly. */
typedef struct graph_record {
    uint32_t v[3];
    double c0, c1;
} graph_record;

/* Collects simplices (possibly with repeats) and hands them over as an fl_graph. */
typedef struct graph_builder {
    int dim, simplex_size;
    size_t vertex_count;
    fl_vec records; /* graph_record */
} graph_builder;

void graph_builder_init(graph_builder *b, int dim, int simplex_size, size_t n);
/* Appends simplex s (simplex_size indices, any order); 0 on success, -1 out of memory. */
int graph_builder_add(graph_builder *b, const uint32_t *s, double c0, double c1);
/* Sorts, removes repeats and moves the result into *out (params only if want_params). */
fl_status graph_builder_finish(graph_builder *b, int want_params, fl_graph *out, fl_error *err);
void graph_builder_free(graph_builder *b);

/* Rejects dim other than 2/3, n beyond 32-bit indices, non-finite and coincident points. */
fl_status graph_check_points(const double *coords, size_t n, int dim, fl_error *err);
fl_status gamma_check_params(const fl_gamma_params *p, fl_error *err);

/* Which simplices a builder should report. */
typedef enum gamma_part { GAMMA_ALL, GAMMA_DELAUNAY_PART, GAMMA_NON_DELAUNAY_PART } gamma_part;

/* Theorem 3.1: every k-subset against every point. */
fl_status gamma_brute_force(const double *coords, size_t n, int dim, const fl_gamma_params *p,
                            gamma_part part, const fl_graph_options *opt, graph_builder *b,
                            fl_error *err);

/* The simplices with an empty ball (c1' >= 0) through the Delaunay triangulation (Thm. 3.2),
 * degenerate sets included; flat sets fall back to the brute force. */
fl_status gamma_delaunay_part(const double *coords, size_t n, int dim, const fl_gamma_params *p,
                              const fl_graph_options *opt, graph_builder *b, fl_error *err);

/* Output-sensitive search for the non-Delaunay edges (c1' < 0) of a 2D γ-graph whose
 * parameters require c1' >= -kappa, kappa < 1 (see gamma_lens.c). */
fl_status gamma_lens_edges(const double *xy, size_t n, const fl_gamma_params *p, double kappa,
                           const fl_graph_options *opt, graph_builder *b, fl_error *err);

/* The non-Delaunay triangles (c1' < 0) of a 3D γ-graph whose parameters require c1' >= -kappa,
 * kappa < 1: candidates around each triangle's shortest edge (gamma3_edges.c), each decided by
 * an early-stopped exact scan (gamma_triangles.c). */
fl_status gamma_lens_triangles(const double *xyz, size_t n, const fl_gamma_params *p, double kappa,
                               const fl_graph_options *opt, graph_builder *b, fl_error *err);

/* ---- a uniform bucket grid for range queries (graph_grid.c) ---- */

typedef struct graph_grid {
    int dim;
    const double *coords;
    size_t n;
    double lo[3], cell; /* cell edge length */
    size_t res[3];      /* cells per axis */
    size_t *start;      /* CSR: cell c holds items[start[c] .. start[c+1]-1] */
    uint32_t *items;
} graph_grid;

/* About two points a cell. Returns FL_ERR_NOMEM on allocation failure. */
fl_status graph_grid_build(graph_grid *g, const double *coords, size_t n, int dim, fl_error *err);
void graph_grid_free(graph_grid *g);
/* Appends to out (uint32_t) every point of the cells meeting the box [lo,hi]: a superset of the
 * points in the box. Returns -1 on allocation failure. */
int graph_grid_box(const graph_grid *g, const double *lo, const double *hi, fl_vec *out);
/* Like graph_grid_box, but only the cells that may meet the slab |normal.(x - center)| <= half
 * (unit normal): a superset of the box's points in the slab, for thin regions such as a γ-lens.
 * Returns -1 on allocation failure. */
int graph_grid_slab(const graph_grid *g, const double *lo, const double *hi, const double *center,
                    const double *normal, double half, fl_vec *out);
/* Appends the points of the cells at Chebyshev cell distance exactly `ring` from the cell of p;
 * every point at Euclidean distance < ring * cell from p lies in rings 0..ring. Returns the
 * number appended, or -1 on allocation failure; 0 with *beyond set once the ring leaves the grid.
 */
long graph_grid_ring(const graph_grid *g, const double *p, size_t ring, fl_vec *out, int *beyond);

/* The exact decision for one triangle t (sorted indices) of the 3D non-Delaunay search: the
 * early-decided witness scan of gamma_triangles.c; adds t to b when it is non-Delaunay and
 * accepted. Returns 0, or -1 out of memory; `ring` is scratch. */
int gamma_triangle_check(const graph_grid *g, const fl_gamma_params *p, double kappa,
                         const uint32_t *t, fl_vec *ring, graph_builder *b);

/* The candidate triangles of gamma_lens_triangles, from their shortest edge (gamma3_edges.c);
 * each goes through gamma_triangle_check. */
fl_status gamma3_edge_triangles(const graph_grid *grid, const fl_gamma_params *p, double kappa,
                                const fl_graph_options *opt, graph_builder *b, fl_error *err);

#endif /* FL_GAMMA_INTERNAL_H */

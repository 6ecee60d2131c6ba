/* Internals of src/skin shared by the skin function (skin_function.c) and the mesher
 * (skin_mesh.c). */
#ifndef FL_SKIN_INTERNAL_H
#define FL_SKIN_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "core/core.h"
#include "flintstone.h"

/* One simplex X of the regular triangulation of the balls (a vertex, edge, triangle or
 * tetrahedron, k = dim) with what the skin needs in its mixed cell (derivation in
 * docs/skin.md, "The skin function"):
 *  - the coordinates mu_f of its focus f, the point of aff(X) with equal power to every ball of
 *    X, in X's frame (origin a = the first centre, edge vectors e_j = z_j - a); the weight w of
 *    the ball (f, w) orthogonal to the balls of X (Cheng & Tan §6.2, b_X^perp) follows
 *    (skin_weight);
 *  - the inverse Gram matrix of the frame, to project onto aff(X).
 * The frame, the focus, w, the reach and the index box are recomputed from the balls when needed
 * (skin_frame, skin_focus, skin_reach; skin_function.c for the box), with the same operations
 * that set mu_f up, so the values are those a stored copy would have: the record went from 360
 * to 168 bytes, which is what decides whether the mixed complex of B* of the npm bunny
 * (~1.2e7 simplices with a positive ball) fits in 4 GB (docs/skin.md, "The bunny"). */
typedef struct skin_simplex {
    double ginv[3][3];
    double mu_f[3];
    /* box_exact SKIN_BOX_VORONOI: the box of X's power face nu_X (the Voronoi vertices around
     * X with their rounding pads). The walk requires v in it as well as the link tests: for a
     * degenerate nu_X (cospherical balls, as in B* of symmetric solids) the link half-spaces
     * all pass through one point and bound a wedge, not the face. SKIN_BOX_CLIPPED (hull
     * simplices, whose power face is unbounded, and faces of slivers, whose Voronoi vertex is
     * not trustworthy; skin_clip.c): a box of the part of nu_X that can meet X's reach box,
     * from the link half-spaces; the index only. Either bounds where the index lists X: the
     * box of X's mixed cell (1-t) X + t nu_X cut to X's box grown by SKIN_REACH_MARGIN times
     * the reach; with box_exact 0 (the subsets of few balls, clips that degenerate) the reach
     * box alone, with a finer nearness test (skin_function.c). */
    double nu_lo[3], nu_hi[3];
    /* The balls of X, sorted, UINT32_MAX padding (the key the mixed-cell walk looks faces and
     * cofaces up by; skin_cell.c). */
    uint32_t ball[4];
    uint8_t k;
    uint8_t box_exact;
    /* 1 when the walk must not trust X's membership test: X is a face of a sliver whose
     * Voronoi vertex is decided by rounding, or its Gram matrix is ill-conditioned (its
     * barycentric coordinates are noise); a walk ending in X falls back to the scan. */
    uint8_t shaky; /* SKIN_SHAKY_* bits (the reason, counted by a FL_SKIN_WALK_STATS build) */
} skin_simplex;
#define SKIN_SHAKY_COND 1u   /* Gram matrix condition > 1e10 */
#define SKIN_SHAKY_SLIVER 2u /* a face of a tetrahedron whose Voronoi vertex is not bounded */
#define SKIN_SHAKY_DEGEN 4u  /* power face possibly degenerate (nu_degenerate) */
/* The bits that make the walk give up on a cell: a face of a sliver (SKIN_SHAKY_SLIVER) is
 * walked, its link tests decided exactly inside their rounding band (skin_link_sign_exact). */
#define SKIN_SHAKY_GIVE_UP (SKIN_SHAKY_COND | SKIN_SHAKY_DEGEN)
/* A simplex the mesher's function does not store in full (every ball of weight <= 0, so G >= 0
 * on its whole mixed cell; skin_function_new_mesher): only what the walk needs to cross its
 * mixed cell. The frame, Gram inverse and focus are recomputed from the balls when the walk
 * enters it (skin_simplex_setup, the same operations as for a stored record), its link is a
 * range of fl_skin_function.link (dropped_link_start). 20 bytes instead of 168 + 8. */
typedef struct skin_light {
    uint32_t ball[4]; /* sorted, UINT32_MAX padding */
    uint8_t k;
    uint8_t shaky; /* SKIN_SHAKY_* bits, as for a stored simplex */
} skin_light;
/* Fills s (frame data, SKIN_SHAKY_COND; no power-face box) for the balls idx[0..k], sorted;
 * -1 for affinely dependent centres (skin_function.c). */
int skin_simplex_setup(const double *xyzw, const uint32_t *idx, int k, skin_simplex *s);
/* skin_exact.c: the exact sign of the walk's link test of ball b for simplex s (k <= 2) at x,
 * i.e. of pi_b(v) - pi_X(v) with v = f + q / t (skin_cell.c): -1, 0 or 1; 2 when it cannot
 * be decided (k = 3, inputs beyond its integer range, out of memory). */
int skin_link_sign_exact(const double *balls, const skin_simplex *s, uint32_t b,
                         const double x[3], double t);
/* The same sign: skin_link_sign_exact first tries a floating-point evaluation with a
 * rigorous error bound (round 14) and calls this big-integer evaluation only when the bound
 * does not decide; tests compare the two (skin_link_filter_off nonzero skips the filter). */
int skin_link_sign_big(const double *balls, const skin_simplex *s, uint32_t b,
                       const double x[3], double t);
extern int skin_link_filter_off;

/* Lexicographic order of two sorted, UINT32_MAX-padded ball keys of a simplex. */
static inline int skin_key_cmp(const uint32_t *a, const uint32_t *b)
{
    for (int i = 0; i < 4; i++)
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    return 0;
}

/* The frame of s from the balls (x, y, z, w each): a = the centre of its first ball and
 * e_j = z_j - a, j < k (rows k.. are zero). */
static inline void skin_frame(const double *balls, const skin_simplex *s, double a[3],
                              double e[3][3])
{
    const double *b0 = balls + 4 * (size_t)s->ball[0];
    for (int c = 0; c < 3; c++)
        a[c] = b0[c];
    for (int j = 0; j < 3; j++) {
        const double *bj = j < s->k ? balls + 4 * (size_t)s->ball[j + 1] : b0;
        for (int c = 0; c < 3; c++)
            e[j][c] = bj[c] - b0[c];
    }
}

/* The focus f = a + sum_j mu_f[j] e_j of s in its frame (a, e). */
static inline void skin_focus(const skin_simplex *s, const double a[3], const double e[3][3],
                              double f[3])
{
    for (int c = 0; c < 3; c++)
        f[c] = a[c];
    for (int i = 0; i < s->k; i++)
        for (int c = 0; c < 3; c++)
            f[c] += s->mu_f[i] * e[i][c];
}

/* The weight w of the ball (f, w) orthogonal to the balls of s, from its frame origin a and
 * focus f: |f - z_0|^2 - w_0 - w = 0. */
static inline double skin_weight(const double *balls, const skin_simplex *s, const double a[3],
                                 const double f[3])
{
    double fa2 = 0;
    for (int c = 0; c < 3; c++)
        fa2 += (f[c] - a[c]) * (f[c] - a[c]);
    return fa2 - balls[4 * (size_t)s->ball[0] + 3];
}

/* The reach of s: sqrt(t * the largest weight of its balls), 0 when none is positive. The
 * combination weight is at most that on X, so G(x) < 0 with X the minimiser puts x within this
 * distance of X (skin_function.c). sqrt(t) sqrt(w), not sqrt(t w): t w underflows to 0 for a
 * subnormal weight, which dropped such a ball's simplices from the index (fuzz_skin). */
static inline double skin_reach(const double *balls, const skin_simplex *s, double t)
{
    double wx = 0;
    for (int i = 0; i <= s->k; i++) {
        double w = balls[4 * (size_t)s->ball[i] + 3];
        wx = w > wx ? w : wx;
    }
    return sqrt(t) * sqrt(wx);
}

/* G(x) on the mixed cell of s, from the barycentric coordinates mu[0..k] of its minimiser z*
 * (mu[0] for the first ball, mu[i] for ball i; frame a, e as skin_frame gives it):
 *     G = |x - z|^2 + t sum_i mu_i |z_i - z|^2 - t sum_i mu_i w_i,   z = sum_i mu_i z_i,
 * the power distance of x to the shrunk combination ball (docs/skin.md, "The skin function"),
 * evaluated relative to a. Equal to the quadric |q|^2 - t/(1-t)|p|^2 + t w_X of the mixed cell
 * in exact arithmetic, but without its cancellation: the quadric subtracts two squares of the
 * distance to the focus, which lies far away for a needle or sliver simplex, and on the npm
 * bunny's B* it gave -1.8e-6 where G = +8.2e-7 (a thin sheet of false "inside" points, hence
 * bubbles; docs/skin.md, round 18). The coordinates are clamped to >= 0 and renormalised, so
 * the value is that of a member of conv(B): never below G(x) beyond rounding. */
static inline double skin_combination_value(const double *balls, const skin_simplex *s, double t,
                                            const double a[3], const double e[3][3],
                                            const double mu[4], const double x[3])
{
    double lam[4], sum = 0, zr[3] = {0, 0, 0}, g = 0, var = 0, ws = 0;
    for (int i = 0; i <= s->k; i++) {
        lam[i] = mu[i] > 0 ? mu[i] : 0;
        sum += lam[i];
    }
    if (!(sum > 0)) return HUGE_VAL;
    for (int i = 0; i <= s->k; i++)
        lam[i] /= sum;
    for (int i = 1; i <= s->k; i++)
        for (int c = 0; c < 3; c++)
            zr[c] += lam[i] * e[i - 1][c];
    for (int c = 0; c < 3; c++) {
        double d = x[c] - a[c] - zr[c];
        g += d * d;
    }
    for (int i = 0; i <= s->k; i++) {
        double v2 = 0;
        for (int c = 0; c < 3; c++) {
            double d = (i ? e[i - 1][c] : 0) - zr[c];
            v2 += d * d;
        }
        var += lam[i] * v2;
        ws += lam[i] * balls[4 * (size_t)s->ball[i] + 3];
    }
    return g + t * (var - ws);
}

/* G(x) from simplex s's mixed cell (skin_function.c): skin_combination_value at the barycentric
 * coordinates of s's minimiser z*; with grad (may be NULL), also 2 (x - z*), the gradient of G
 * there. Never below G(x) beyond rounding; G(x) when z* lies in s. The scan takes its minimum
 * over the candidates, the edge roots and vertex offsets (skin_root.c) read it in the cell the
 * walk found. */
double skin_simplex_value(const fl_skin_function *sk, const skin_simplex *s, const double x[3],
                          double grad[3]);

struct fl_skin_function {
    double t;
    double wmax; /* largest ball weight (> 0) */
    size_t simplex_count;
    skin_simplex *simplex;
    /* Uniform grid index: cell c lists the simplices X whose registration box (lo, hi) meets
     * it (CSR arrays cell_start[cells+1], cell_item[]); simplices of reach 0 are in no list. */
    double origin[3], cell;
    size_t dims[3];
    size_t *cell_start;
    uint32_t *cell_item;
    /* The registration box of each simplex in float (lo xyz, hi xyz, rounded outwards; empty
     * for simplices in no list): the scan skips the candidates whose box does not hold x
     * (skin_value_scan; round 13). */
    float *scan_box;
    /* The mixed complex for point location (skin_cell.c), only for the regular-triangulation
     * path (walkable = 1; the few-ball subset path scans): the simplices are sorted by ball[],
     * link_start/link list the link of each simplex (the balls b with X + b a simplex), balls
     * is a copy of the input, and *hint the simplex of the previous evaluation (relaxed atomic:
     * any value is a correct start, so concurrent callers only lose speed). */
    int walkable;
    double *balls; /* a copy of the input (every path: the simplices' frames are read from it) */
    size_t ball_count;
    /* walkable only: the stored (dropped) simplices whose smallest ball is b are
     * simplex[first_stored[b] .. first_stored[b + 1]) (dropped[first_dropped[b] ..]): the walk
     * looks a key up in that range, not in all of them (round 14) */
    size_t *first_stored, *first_dropped;
    /* walkable only: per index cell, the cell of the walk that located the cell's centre
     * (UINT32_MAX for a cell without list): where the walk from the caller's start gives up it
     * restarts here (skin_seed_cells, skin_cell.c; round 15) */
    uint32_t *cell_seed;
    size_t *link_start;
    uint32_t *link;
    /* The mesher's function only (skin_function_new_mesher): the simplices it does not store,
     * sorted by ball[], with their links (link[dropped_link_start[j] ..
     * dropped_link_start[j + 1]]). The walk numbers them simplex_count + j (skin_cell.c). */
    size_t dropped_count;
    skin_light *dropped;
    size_t *dropped_link_start;
    _Atomic uint32_t *hint;
};

/* ==== mixed-cell point location (skin_cell.c; added by h-skinspeed) ====
 * skin_value_walk: G(x) by locating the mixed cell of x with a walk from simplex *start
 * (updated to the cell found) and evaluating that one quadric; falls back to the candidate scan
 * when the walk does not end within its step cap (degenerate cells, rounding) or the function is
 * not walkable. fl_skin_function_value calls it with the shared hint; a caller with its own
 * sequence of nearby points (one per thread) can keep its own start (initialise to 0).
 * skin_value_scan: the candidate scan alone (the reference the tests compare the walk with).
 * skin_index_cell: the index cell holding x (0 when x is outside the index). */
double skin_value_walk(const fl_skin_function *skin, const double x[3], uint32_t *start);
double skin_value_scan(const fl_skin_function *skin, const double x[3]);
int skin_index_cell(const fl_skin_function *skin, const double x[3], size_t *cell);
/* skin_index_centre: the centre of index cell id (numbered x fastest, then y, then z). */
void skin_index_centre(const fl_skin_function *skin, size_t id, double c[3]);
/* skin_function_new_mesher: fl_skin_function_new keeping only the simplices with a positive
 * ball. The others (every ball of weight <= 0) have G >= 0 on their whole mixed cell
 * (G = |x - z|^2 - t w(z) there, w(z) <= max w over X <= 0), are never in the index and never
 * the minimiser of a G <= 0; they keep a light record (skin_light) that the walk crosses and
 * answers in (their quadric, >= 0; skin_cell.c). Where the walk gives up it scans, whose value
 * is G where G <= 0 and >= G > 0 elsewhere. So the sign of G, its value where G <= 0 and
 * the zeros are those of the full function, which is all the meshers use; positive values may
 * be overestimates (fl_skin_function_value keeps every simplex). On B* of the eps-approximation
 * two thirds of the balls are negative: the npm bunny's 854378 B* balls gave ~3e7 simplices of
 * 360 bytes (docs/skin.md). */
fl_status skin_function_new_mesher(const double *xyzw, size_t n, double t,
                                   fl_skin_function **out, fl_error *err);
/* skin_clip_boxes (skin_clip.c): for the simplices whose power-face box is not known from
 * Voronoi vertices (faces of slivers, hull simplices; box_exact 0), a conservative box of the
 * part of nu_X that can meet the reach box, from the link half-spaces; sets nu_lo/nu_hi and
 * box_exact = SKIN_BOX_CLIPPED where it succeeds. Only the index uses it (reg_box); the walk's
 * box test reads box_exact == SKIN_BOX_VORONOI boxes only. margin: SKIN_REACH_MARGIN. */
/* How far around a simplex X its fallback index cells reach, in units of X's reach: the index
 * then lists X wherever G < (margin^2 - 1) t max w_X could have X as the minimiser, so G is
 * exact there, not only where it is negative; the mesher's root finding along grid edges
 * (skin_mesh.c) needs values on the outside end of an edge to converge fast. */
#define SKIN_REACH_MARGIN 1.5
#define SKIN_BOX_VORONOI 1
#define SKIN_BOX_CLIPPED 2
fl_status skin_clip_boxes(fl_skin_function *sk, double margin, fl_error *err);
/* Tests only: nonzero makes the functions built afterwards skip skin_clip_boxes (the index
 * then lists those simplices in their whole reach box, as before round 14). */
extern int skin_clip_off;
/* Whether the index lists s, with the box it lists s in (its mixed cell's box cut to its reach
 * box; skin_function.c). */
int skin_listed_box(const fl_skin_function *sk, const skin_simplex *s, double lo[3],
                    double hi[3]);
/* skin_seed_cells (skin_cell.c): fills sk->cell_seed (walkable functions with an index). */
fl_status skin_seed_cells(fl_skin_function *sk, fl_error *err);
/* end of mixed-cell point location */


/* ==== exact vertices on the skin (skin_root.c) ====
 * skin_locate: the mixed cell of x (a simplex index, *start updated to it) with *val = G(x), or
 * SKIN_NO_CELL when the walk gave up or the function is not walkable (*val then from the scan).
 * skin_edge_root: a zero of G on the segment a -> b, G(a) < 0 <= G(b), to rounding; ca and cb
 * are the mixed cells of a and b when the caller knows them (else SKIN_NO_CELL). When both ends
 * lie in one mixed cell the segment does too (mixed cells are convex) and G on it is that
 * cell's quadric, a quadratic in the parameter, solved in closed form without evaluating G;
 * otherwise regula falsi until the bracket's ends share a cell. *hint: a walk start (the
 * caller's, or NULL for the function's shared one). Adds the evaluations of G to *evaluations.
 * skin_vertex_offset: max over the points of |G(v)| / |grad G(v)|, the gradient of the located
 * cell's quadric (central differences at step 1e-5 h where no cell is found).
 * skin_hand_over: moves the vertex (double[3]) and triangle (uint32_t[3]) vectors into out. */
#define SKIN_NO_CELL UINT32_MAX
uint32_t skin_locate(const fl_skin_function *sk, const double x[3], uint32_t *start, double *val);
/* skin_locate with *why: 0 when the walk answered in a stored cell, SKIN_WHY_DROPPED when it
 * answered in a dropped cell (G >= 0 there; SKIN_NO_CELL is returned, *val is the cell's
 * quadric), else why it gave up and scanned: SKIN_WHY_MISSING (a neighbour not listed at all),
 * SKIN_WHY_BOX, SKIN_WHY_CAP (the step cap), SKIN_WHY_CYCLE (the walk came back to a cell it
 * had left: rounding ping-pong), or SKIN_WHY_SHAKY | the cell's SKIN_SHAKY_* bits; -1 when the
 * function is not walkable or x is not finite. SKIN_WHY_SEARCHED (| SKIN_WHY_DROPPED for a
 * dropped cell): the walk gave up but the search round the cell it stopped in found x's cell
 * (skin_cell.c, give_up_search), which answered; no scan. */
enum { SKIN_WHY_MISSING = 1, SKIN_WHY_BOX = 2, SKIN_WHY_CAP = 3, SKIN_WHY_CYCLE = 4,
       SKIN_WHY_DROPPED = 5, SKIN_WHY_SHAKY = 8, SKIN_WHY_SEARCHED = 16 };
uint32_t skin_locate_why(const fl_skin_function *sk, const double x[3], uint32_t *start,
                         double *val, int *why);
void skin_edge_root(const fl_skin_function *g, const double a[3], const double b[3], uint32_t ca,
                    uint32_t cb, uint32_t *hint, double x[3], size_t *evaluations);
double skin_vertex_offset(const fl_skin_function *g, const double *xyz, size_t count, double h,
                          size_t *evaluations);
void skin_hand_over(fl_vec *xyz, fl_vec *tri, fl_mesh *out);
/* end of exact vertices on the skin */

/* The graded mesher (skin_graded.c): marching tetrahedra on the Delaunay tetrahedralization of
 * the corners of an octree refined by the local feature size of the skin. Same contract as the
 * uniform path of fl_skin_mesh; g is the skin function of the balls, o->cell (> 0) the largest
 * cell. boxes (skin_box, or NULL): the local repair's requests (skin_mesh.c), each asking for
 * cells of at most its h over the ball round it; a point (lo == hi) asks for it there. Fills out
 * and the grid fields of stats (cell = the smallest leaf, cubes = leaves). */
fl_status skin_graded_mesh(const fl_skin_function *g, const double *xyzw, size_t n,
                           const fl_skin_options *o, const fl_vec *boxes, fl_mesh *out,
                           fl_skin_stats *stats, fl_error *err);

/* fl_skin_mesh, with stats->max_vertex_offset measured only when `offsets` (it costs a walk
 * a vertex; fl_skin_approx_build measures the certified distance instead). betti: the Betti
 * numbers of the union (fl_balls_union_betti) when the caller has them, for the repair; NULL
 * lets the repair compute them. */
fl_status skin_mesh_run(const double *xyzw, size_t n, const fl_skin_options *opt, fl_mesh *out,
                        fl_skin_stats *stats, int offsets, const long long *betti, fl_error *err);

/* A box [lo, hi] that wants cells of at most h (skin_defects.c -> skin_graded.c). */
typedef struct skin_box {
    double lo[3], hi[3], h;
} skin_box;

/* Connected components of a mesh's triangles; -1 when out of memory (skin_defects.c). */
long long skin_mesh_components(const fl_mesh *m);

/* Appends to boxes (skin_box) a box round the local handles of the closed 2-manifold mesh m
 * when `handles` (the smallest windows of 8 to 16 local face sizes whose part has genus) and
 * round its extra_components smallest components (skin_defects.c). FL_ERR_INPUT when m is not
 * closed and 2-manifold. */
fl_status skin_mesh_defects(const fl_mesh *m, const double *xyzw, size_t n, int handles,
                            long long extra_components, fl_vec *boxes, fl_error *err);
#endif

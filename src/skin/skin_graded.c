/* The graded skin mesher: marching tetrahedra on a tetrahedralization of the corners of an
 * octree whose leaves are small only where the skin has small features.
 *
 * Why: the skin of the eps-approximation's B* (Cheng & Tan §6.2) has parts of very different
 * sizes: near a sharp vertex of the polyhedron the protecting balls shrink with the local gap
 * size (§4, lgs -> 0) and the skin between them is as thin as they are, while the interior
 * balls of B_perp are large. A uniform grid fine enough for the smallest balls is too large;
 * one coarse enough to be affordable cut the thin parts (the tetrahedron at eps 0.15,
 * docs/skin.md).
 *
 * Why the result is a closed 2-manifold for every input, with no crack between leaves of
 * different sizes: the octree only supplies points; their regular triangulation with tiny
 * generic weights (corner_triangulation, fl_rt3, exact) is one conforming triangulation of
 * their convex hull, the root cube. Each point gets one label (G < 0 or not), so the output
 * is the level set of a piecewise-linear interpolant at a regular value (as in the uniform
 * mesher, skin_mesh.c),
 * and the root cube's boundary lies outside every ball, hence outside the body
 * (body^t ⊂ ∪B, §6.1), so the level set does not reach the hull. Hanging nodes do not matter:
 * nothing is interpolated on octree faces.
 *
 * Local size: every simplex X of the regular triangulation whose focus f lies in X contributes
 * a feature at f of size sqrt(min(t, 1 - t) |w_X|), w_X the weight of its orthogonal ball: by
 * the quadric of the mixed cell (docs/skin.md, G = |q|^2 - t/(1-t) |p|^2 + t w_X) that is the
 * shrunk radius sqrt(t w) of a ball (X a vertex), the waist of a neck (an edge, w_X < 0), the
 * half-thickness of a membrane (a triangle) and the radius of a spherical cavity (a
 * tetrahedron, w_X > 0). The wanted cell near a feature is `grade` times its size, growing by
 * half the distance away from it (a 1/2-Lipschitz size function keeps neighbouring leaves of
 * similar size, so the tetrahedra stay reasonable).
 *
 * Critical foci as grid points (round 16): in the mixed cell of X, G is the quadric centred at
 * the focus f, so G has a critical point exactly where f lies in the mixed cell, i.e. in X and
 * in nu_X; its index is dim X and its value t w_X. An edge's is the saddle in the middle of a
 * neck (w_X < 0) or of a gap between two sheets (w_X > 0), a triangle's the middle of a
 * membrane or of a tunnel, a tetrahedron's the centre of a cavity. The topology of the skin
 * changes only where such a value crosses 0, so a thin neck, gap, membrane, tunnel or cavity
 * has a critical point in its middle with the sign that keeps it open or closed. The foci of
 * the critical simplices are added to the corners, each labelled by G like any corner, so the
 * PL interpolant has the right sign at every critical point of G: a gap narrower than the
 * cells can no longer be bridged through its middle, a neck no longer cut there. On 80 random
 * 100-ball sets (bench/workloads/skin.sh's generator) the Euler characteristic is wrong on 1
 * at grade 1.5 (9 without the foci) and on 27 at grade 2.2 (58 without), for 0.5 % more
 * vertices. Not enough where the cells are several times a feature's width: an isolated focus
 * cannot join the rest of its gap (the npm bunny's grade-4 mesh keeps its two false handles,
 * and gains an 18-vertex bubble round a focus of a 1e-4-sized pocket; docs/skin.md). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "skin/skin_internal.h"
#include "skin/skin_map.h"

#define OCT_DEPTH 19     /* leaves down to root / 2^19; corners fit 20 bits an axis */
#define OCT_BITS 21      /* bits an axis in a packed corner key */
#define GRADE_SLOPE 0.5  /* the size function grows by this times the distance */
#define FOCUS_SLACK 1e-9 /* barycentric slack of "the focus lies in X" */

/* A feature: the ball (c, r) (r = 0 for a point) wanting cells of size h within it. */
typedef struct size_src {
    double c[3], r, h;
} size_src;

typedef struct octree {
    double origin[3], root;
    const size_src *src;
    fl_vec stack; /* uint32_t source indices: the current cell's forcing sources, then its
                     children's */
    u64map corner;
    fl_vec pts; /* double[3] per corner */
    size_t leaves, max_leaves;
    double hsmall; /* the smallest leaf */
} octree;

/* Distance from the box [lo, lo + L]^3 to the ball of s (0 when they meet). */
static double box_ball_dist(const double lo[3], double L, const size_src *s)
{
    double d2 = 0;
    for (int c = 0; c < 3; c++) {
        double e = fmax(fmax(lo[c] - s->c[c], s->c[c] - lo[c] - L), 0);
        d2 += e * e;
    }
    return fmax(sqrt(d2) - s->r, 0);
}

static uint64_t corner_key(uint64_t i, uint64_t j, uint64_t k)
{
    return (k << (2 * OCT_BITS)) | (j << OCT_BITS) | i;
}

/* Registers the 8 corners of a leaf at level `depth` with integer position (i, j, k). */
static fl_status add_leaf(octree *o, int depth, const uint64_t ijk[3], fl_error *err)
{
    int sh = OCT_DEPTH - depth;
    double unit = o->root / (double)((uint64_t)1 << OCT_DEPTH);
    o->hsmall = fmin(o->hsmall, o->root / (double)((uint64_t)1 << depth));
    if (++o->leaves > o->max_leaves)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "skin: the graded grid would have more than %zu leaves; choose a larger "
                       "cell or grade",
                       o->max_leaves);
    for (unsigned b = 0; b < 8; b++) {
        uint64_t q[3];
        for (int c = 0; c < 3; c++)
            q[c] = (ijk[c] + (b >> c & 1)) << sh;
        uint64_t key = corner_key(q[0], q[1], q[2]);
        size_t s = map_slot(&o->corner, key);
        if (o->corner.key[s] == key) continue;
        double x[3];
        for (int c = 0; c < 3; c++)
            x[c] = o->origin[c] + unit * (double)q[c];
        if (fl_vec_push(&o->pts, x, 1) ||
            map_put(&o->corner, key, (uint32_t)(o->pts.count - 1)) == SIZE_MAX)
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
        if (o->pts.count >= UINT32_MAX - 8)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: more than 2^32 grid points");
    }
    return FL_OK;
}

/* The cell at level depth, position ijk, whose forcing sources are stack[off, off + cnt):
 * a leaf when none forces it, else split, each child keeping the sources that force it
 * (a source that does not force a cell forces none of its children: they are nearer to it by
 * no more and want a cell half as large). */
static fl_status refine(octree *o, int depth, const uint64_t ijk[3], size_t off, size_t cnt,
                        fl_error *err)
{
    if (cnt == 0 || depth == OCT_DEPTH) return add_leaf(o, depth, ijk, err);
    double half = o->root / (double)((uint64_t)1 << (depth + 1));
    for (unsigned b = 0; b < 8; b++) {
        uint64_t q[3];
        double lo[3];
        for (int c = 0; c < 3; c++) {
            q[c] = 2 * ijk[c] + (b >> c & 1);
            lo[c] = o->origin[c] + half * (double)q[c];
        }
        size_t top = off + cnt, kept = 0;
        o->stack.count = top;
        for (size_t i = 0; i < cnt; i++) {
            uint32_t id = ((const uint32_t *)o->stack.data)[off + i];
            const size_src *s = &o->src[id];
            if (!(s->h + GRADE_SLOPE * box_ball_dist(lo, half, s) < half)) continue;
            if (fl_vec_push(&o->stack, &id, 1))
                return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
            kept++;
        }
        fl_status st = refine(o, depth + 1, q, top, kept, err);
        if (st != FL_OK) return st;
    }
    return FL_OK;
}

/* 1 when the focus of X lies in the closed simplex X (mu_f are its barycentric coordinates
 * beyond the first vertex). */
static int focus_inside(const skin_simplex *s)
{
    double sum = 0;
    for (int j = 0; j < s->k; j++) {
        if (!(s->mu_f[j] >= -FOCUS_SLACK)) return 0;
        sum += s->mu_f[j];
    }
    return sum <= 1 + FOCUS_SLACK;
}

/* 1 when the focus f of stored simplex id also lies in its power face nu_X, i.e. f is a
 * critical point of G (f in X and f in nu_X put f = (1 - t) f + t f in the mixed cell, where G
 * is the quadric centred at f): the link tests of the walk at v = f (skin_cell.c), with a
 * generous slack (a false 1 only adds a grid point). 0 without links (the few-ball path). */
static int focus_critical(const fl_skin_function *g, size_t id, const double a[3],
                          const double f[3])
{
    if (!g->walkable || !g->link_start) return 0;
    const skin_simplex *x = &g->simplex[id];
    const double *b0 = g->balls + 4 * (size_t)x->ball[0];
    double fa[3] = {f[0] - a[0], f[1] - a[1], f[2] - a[2]};
    double fl = sqrt(fa[0] * fa[0] + fa[1] * fa[1] + fa[2] * fa[2]);
    for (size_t l = g->link_start[id]; l < g->link_start[id + 1]; l++) {
        const double *b = g->balls + 4 * (size_t)g->link[l];
        double eb[3] = {b[0] - b0[0], b[1] - b0[1], b[2] - b0[2]};
        double e2 = eb[0] * eb[0] + eb[1] * eb[1] + eb[2] * eb[2];
        /* pi_b(f) - pi_X(f) = -2 (f - a).e_b + |e_b|^2 - w_b + w_a */
        double h = -2 * (fa[0] * eb[0] + fa[1] * eb[1] + fa[2] * eb[2]) + e2 - b[3] + b0[3];
        double tol = 1e-9 * (2 * fl * sqrt(e2) + e2 + fabs(b[3]) + fabs(b0[3]));
        if (h < -tol) return 0;
    }
    return 1;
}

/* The features (header comment): every positive ball, and the simplices with a positive ball
 * whose focus lies in them. Sizes are capped at hmax and floored at a sixteenth of the
 * smallest ball's, so one near-tangent pair (|w_X| -> 0) cannot blow the tree up. The foci of
 * the critical ones (focus_critical) go to `foci`, to be grid points themselves. */
static fl_status make_sources(const fl_skin_function *g, const double *xyzw, size_t n, double t,
                              double grade, double hmax, const fl_vec *boxes, fl_vec *src,
                              fl_vec *foci, fl_error *err)
{
    /* the boxes of local refinement (fl_skin_options.repair): each is a source of size b->h
     * over the ball circumscribing it (radius 0 for a point, lo == hi: the repair's mesh
     * vertices) */
    for (size_t i = 0; boxes && i < boxes->count; i++) {
        const skin_box *b = (const skin_box *)boxes->data + i;
        size_src s = {{0, 0, 0}, 0, b->h};
        for (int c = 0; c < 3; c++) {
            s.c[c] = (b->lo[c] + b->hi[c]) / 2;
            s.r += (b->hi[c] - b->lo[c]) * (b->hi[c] - b->lo[c]) / 4;
        }
        s.r = sqrt(s.r);
        if (!(s.h > 0) || !isfinite(s.r) || !isfinite(s.c[0] + s.c[1] + s.c[2])) continue;
        if (fl_vec_push(src, &s, 1))
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    }
    double hmin = HUGE_VAL;
    for (size_t i = 0; i < n; i++) {
        const double *b = xyzw + 4 * i;
        if (!(b[3] > 0)) continue;
        size_src s = {{b[0], b[1], b[2]}, sqrt(b[3]), fmin(hmax, grade * sqrt(t * b[3]))};
        hmin = fmin(hmin, s.h);
        if (fl_vec_push(src, &s, 1))
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    }
    double floor_h = hmin / 16, mt = fmin(t, 1 - t);
    for (size_t i = 0; i < g->simplex_count; i++) {
        const skin_simplex *x = &g->simplex[i];
        if (!(skin_reach(g->balls, x, g->t) > 0) || !focus_inside(x)) continue;
        double za[3], ze[3][3], f[3];
        skin_frame(g->balls, x, za, ze);
        skin_focus(x, za, ze, f);
        if (x->k == 0) { /* a ball: its centre is a minimum of G when in its power cell (its
                          * size is the ball's source above) */
            if (focus_critical(g, i, za, f) && fl_vec_push(foci, f, 1))
                return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
            continue;
        }
        double a = fabs(skin_weight(g->balls, x, za, f));
        size_src s = {{f[0], f[1], f[2]}, sqrt(a), grade * sqrt(mt * a)};
        s.h = fmin(hmax, fmax(s.h, floor_h));
        if (!isfinite(s.h) || !isfinite(s.r) || !isfinite(f[0] + f[1] + f[2])) continue;
        if (focus_critical(g, i, za, f) && fl_vec_push(foci, f, 1))
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
        if (fl_vec_push(src, &s, 1))
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    }
    return FL_OK;
}

/* The octree's points: root cube around the positive balls' box with a margin of hmax, grid
 * offset by an odd fraction as in skin_mesh.c (setup_grid) so round inputs do not put points
 * on the skin. */
static fl_status build_points(octree *o, const double *xyzw, size_t n, const fl_vec *src,
                              double hmax, fl_error *err)
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (size_t i = 0; i < n; i++) {
        const double *b = xyzw + 4 * i;
        if (!(b[3] > 0)) continue;
        double r = sqrt(b[3]);
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], b[c] - r);
            hi[c] = fmax(hi[c], b[c] + r);
        }
    }
    double side = 0;
    for (int c = 0; c < 3; c++)
        side = fmax(side, hi[c] - lo[c]);
    o->root = side + 2.6 * hmax;
    for (int c = 0; c < 3; c++)
        o->origin[c] = lo[c] - (1 + 0.3183098861837907 * (c + 1) / 3) * hmax;
    o->src = src->data;
    o->hsmall = HUGE_VAL;
    size_t est = o->max_leaves < 4096 ? 4096 : o->max_leaves / 64;
    if (map_init(&o->corner, est))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    for (size_t i = 0; i < src->count; i++) { /* the root is forced by every source */
        uint32_t id = (uint32_t)i;
        if (fl_vec_push(&o->stack, &id, 1))
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    }
    const uint64_t zero[3] = {0, 0, 0};
    return refine(o, 0, zero, 0, src->count, err);
}

/* ---- marching tetrahedra on the corner tetrahedra ---- */

typedef struct dmarch {
    const fl_skin_function *g;
    const double *p;
    const uint8_t *in; /* per corner: bit 0 G < 0, bit 1 start[] is its own mixed cell */
    const uint32_t *start; /* per corner: the cell the walk ended in at it (label_and_march) */
    u64map vert; /* edge (lo index << 32 | hi index) -> vertex */
    fl_vec xyz, tri;
    size_t evaluations;
    uint32_t hint; /* the walk's start */
} dmarch;

static uint32_t dedge_vertex(dmarch *m, uint32_t a, uint32_t b)
{
    uint64_t key = a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
    size_t s = map_slot(&m->vert, key);
    if (m->vert.key[s] == key) return m->vert.val[s];
    uint32_t ins = m->in[a] & 1 ? a : b, outs = m->in[a] & 1 ? b : a;
    double x[3];
    /* the root's walks start in the inside corner's cell, and when both corners lie in one
     * mixed cell the root is that quadric's, without a walk (skin_edge_root). The tetrahedra
     * come in the triangulation's order, not space's: with the previous root's cell as the
     * start, the npm bunny's graded mesher (grade 4) restarted far for most roots (round 15) */
    m->hint = m->start[ins];
    skin_edge_root(m->g, m->p + 3 * (size_t)ins, m->p + 3 * (size_t)outs,
                   m->in[ins] & 2 ? m->start[ins] : SKIN_NO_CELL,
                   m->in[outs] & 2 ? m->start[outs] : SKIN_NO_CELL, &m->hint, x, &m->evaluations);
    uint32_t v = (uint32_t)m->xyz.count;
    if (fl_vec_push(&m->xyz, x, 1)) return UINT32_MAX;
    return map_put(&m->vert, key, v) == SIZE_MAX ? UINT32_MAX : v;
}

/* Triangle (v0, v1, v2), reversed when flip. */
static int dpush(dmarch *m, uint32_t v0, uint32_t v1, uint32_t v2, int flip)
{
    uint32_t t[3] = {v0, flip ? v2 : v1, flip ? v1 : v2};
    return fl_vec_push(&m->tri, t, 1);
}

/* One tetrahedron with corners c[4] (point indices). Orientation without arithmetic on the
 * vertices: with a the lone corner (one vs three) or an inside corner (two vs two) and b, c, d
 * ordered as below, the triangle (ab, ac, ad) resp. the quad (ac, ad, bd, bc) has its normal
 * n with n.(a - plane) = -det[b - a, c - a, d - a] / 8 at the edge midpoints (expand the
 * cross product), and moving the vertices along their edges keeps the combinatorics. The
 * normal must point away from the inside, and det[b - a, c - a, d - a] =
 * -fl_orient3d(a, b, c, d), decided exactly. */
static int dmarch_tet(dmarch *m, const uint32_t *c)
{
    int ins[4], outs[4], ni = 0, no = 0;
    for (int i = 0; i < 4; i++) {
        if (m->in[c[i]] & 1)
            ins[ni++] = i;
        else
            outs[no++] = i;
    }
    if (ni == 0 || no == 0) return 0;
    uint32_t a, b, cc, d;
    int a_inside;
    if (ni == 1 || no == 1) {
        const int *lone = ni == 1 ? ins : outs, *rest = ni == 1 ? outs : ins;
        a = c[lone[0]], b = c[rest[0]], cc = c[rest[1]], d = c[rest[2]];
        a_inside = ni == 1;
    } else {
        a = c[ins[0]], b = c[ins[1]], cc = c[outs[0]], d = c[outs[1]];
        a_inside = 1;
    }
    int o = fl_orient3d(m->p + 3 * (size_t)a, m->p + 3 * (size_t)b, m->p + 3 * (size_t)cc,
                        m->p + 3 * (size_t)d);
    /* keep the order when the normal points away from an inside a (det > 0, o < 0) or towards
     * an outside a (o > 0) */
    int flip = a_inside ? o > 0 : o < 0;
    if (ni == 1 || no == 1) {
        uint32_t v0 = dedge_vertex(m, a, b), v1 = dedge_vertex(m, a, cc),
                 v2 = dedge_vertex(m, a, d);
        if (v0 == UINT32_MAX || v1 == UINT32_MAX || v2 == UINT32_MAX) return -1;
        return dpush(m, v0, v1, v2, flip);
    }
    uint32_t v[4] = {dedge_vertex(m, a, cc), dedge_vertex(m, a, d), dedge_vertex(m, b, d),
                     dedge_vertex(m, b, cc)};
    for (int i = 0; i < 4; i++)
        if (v[i] == UINT32_MAX) return -1;
    if (dpush(m, v[0], v[1], v[2], flip)) return -1;
    return dpush(m, v[0], v[2], v[3], flip);
}

static fl_status march_delaunay(dmarch *m, const fl_rt3 *dt, const fl_skin_options *o,
                                fl_error *err)
{
    if (map_init(&m->vert, dt->tet_count / 8 + 64))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    for (size_t i = 0; i < dt->tet_count; i++) {
        if ((i & 16383) == 0 && fl_progress(o->progress, o->progress_user, "skin",
                                            0.5 + 0.5 * (double)i / (double)dt->tet_count))
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
        if (dmarch_tet(m, dt->tet + 4 * i))
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
        if (m->xyz.count >= UINT32_MAX - 8)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: more than 2^32 vertices");
    }
    return FL_OK;
}

/* A triangulation of the octree's corners. The corners are exactly degenerate for the
 * Delaunay in-sphere test (the 8 corners of every leaf are cospherical), so fl_dt3_build
 * decided nearly every test in exact arithmetic with its symbolic perturbation (60 % of the
 * graded mesher's time on a 200-ball set). Any triangulation of the corners serves (the
 * output is the level set of the PL interpolant, closed for every triangulation whose hull
 * lies outside the balls), so the corners get tiny pseudo-random weights, at most
 * CORNER_WEIGHT times the smallest leaf squared, and the regular triangulation of these
 * balls is used: a generic lifting, decided by the floating-point filters. It is still exact
 * (fl_rt3_build), so a valid triangulation of the corners' convex hull, the root cube, whose
 * 8 corners are extreme and never hidden; a hidden inner corner is simply not used.
 * The weight is a hash of the point's coordinates (round 17; it was the next number of one
 * sequence in point order), so adding points in one place leaves the triangulation elsewhere
 * as it was: the regular triangulation is unique, and a tetrahedron changes only when a new
 * point lies in its orthogonal ball. Local refinement (fl_skin_options.repair) needs that:
 * with the sequence, refining two boxes of the npm bunny re-drew every weight after them and a
 * false handle appeared elsewhere (docs/skin.md round 16). The weight bound follows the
 * smallest leaf, so a refinement scales every weight alike; that keeps how the weights break
 * the ties of exactly cospherical corners (on a common sphere |p|^2 is affine in p, so the
 * lifted points' lower hull depends on the weights only up to a positive factor), and the
 * other configurations are decided by the positions, far above the weights. */
#define CORNER_WEIGHT 1e-2
static fl_status corner_triangulation(const octree *ot, fl_rt3 *rt, fl_error *err)
{
    size_t n = ot->pts.count;
    double *b = fl_alloc_array(n, 4 * sizeof(double));
    if (!b) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    const double *p = ot->pts.data, wmax = CORNER_WEIGHT * ot->hsmall * ot->hsmall;
    for (size_t i = 0; i < n; i++) {
        uint64_t h = 0x9e3779b97f4a7c15u;
        for (int c = 0; c < 3; c++) {
            uint64_t bits;
            memcpy(&bits, p + 3 * i + c, sizeof bits);
            h = mix64(h ^ bits);
            b[4 * i + c] = p[3 * i + c];
        }
        b[4 * i + 3] = wmax * (double)(h >> 11) * 0x1p-53;
    }
    fl_status st = fl_rt3_build(b, n, NULL, rt, err);
    free(b);
    return st;
}

/* Labels every point (G < 0), then marches. */
static fl_status label_and_march(dmarch *m, const octree *ot, const fl_skin_options *o,
                                 fl_error *err)
{
    fl_rt3 dt;
    fl_status st = corner_triangulation(ot, &dt, err);
    if (st != FL_OK) return st;
    uint8_t *in = fl_alloc_array(ot->pts.count, 1);
    uint32_t *start = fl_alloc_array(ot->pts.count, sizeof *start);
    if (!in || !start) {
        free(in);
        free(start);
        fl_rt3_free(&dt);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    }
    uint32_t h = 0;
    for (size_t i = 0; i < ot->pts.count; i++) {
        if ((i & 16383) == 0 &&
            fl_progress(o->progress, o->progress_user, "skin", 0.5 * (double)i / ot->pts.count)) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
            break;
        }
        double v;
        uint32_t c = skin_locate(m->g, (const double *)ot->pts.data + 3 * i, &h, &v);
        in[i] = (uint8_t)((v < 0) | (c != SKIN_NO_CELL) << 1);
        start[i] = h;
    }
    m->evaluations += ot->pts.count;
    m->p = ot->pts.data;
    m->in = in;
    m->start = start;
    if (!st) st = march_delaunay(m, &dt, o, err);
    free(in);
    free(start);
    m->in = NULL;
    m->start = NULL;
    fl_rt3_free(&dt);
    return st;
}

fl_status skin_graded_mesh(const fl_skin_function *g, const double *xyzw, size_t n,
                           const fl_skin_options *o, const fl_vec *boxes, fl_mesh *out,
                           fl_skin_stats *stats, fl_error *err)
{
    octree ot;
    memset(&ot, 0, sizeof ot);
    fl_vec_init(&ot.stack, sizeof(uint32_t));
    fl_vec_init(&ot.pts, 3 * sizeof(double));
    ot.max_leaves = o->max_cubes;
    fl_vec src;
    fl_vec_init(&src, sizeof(size_src));
    dmarch m;
    memset(&m, 0, sizeof m);
    m.g = g;
    fl_vec_init(&m.xyz, 3 * sizeof(double));
    fl_vec_init(&m.tri, 3 * sizeof(uint32_t));
    fl_vec foci;
    fl_vec_init(&foci, 3 * sizeof(double));
    fl_status st = make_sources(g, xyzw, n, g->t, o->grade, o->cell, boxes, &src, &foci, err);
    if (!st) st = build_points(&ot, xyzw, n, &src, o->cell, err);
    if (!st && foci.count && fl_vec_push(&ot.pts, foci.data, foci.count))
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    fl_vec_free(&foci);
    fl_vec_free(&ot.stack);
    map_free(&ot.corner);
    fl_vec_free(&src);
    if (!st) st = label_and_march(&m, &ot, o, err);
    if (!st && m.tri.count == 0)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "skin: no grid point lies inside the skin; choose a finer grade or cell");
    if (!st && stats) {
        stats->cell = ot.hsmall;
        stats->cubes = ot.leaves;
        stats->evaluations = m.evaluations;
    }
    if (!st) skin_hand_over(&m.xyz, &m.tri, out);
    fl_vec_free(&ot.pts);
    fl_vec_free(&m.xyz);
    fl_vec_free(&m.tri);
    map_free(&m.vert);
    return st;
}

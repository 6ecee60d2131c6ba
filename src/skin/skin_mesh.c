/* Triangulating skin^t(B): marching tetrahedra on the Kuhn subdivision of a cubic grid, with
 * every vertex placed on the skin along its grid edge (skin_root.c: in closed form from the
 * mixed-cell quadric when both ends share a cell, else regula falsi).
 *
 * Why this is a closed 2-manifold for every input: the six Kuhn tetrahedra of every cube (the
 * paths from corner 000 to 111) fit across cube faces, so together they form one conforming
 * triangulation of the visited cubes. Each grid point gets one label, inside (G < 0) or not,
 * so the surface is the boundary of the union of "inside" regions of the piecewise-linear
 * interpolant at a regular value; it has no boundary and every edge lies in two triangles.
 * Only cubes with corners of both labels carry triangles; the cubes skipped (cube_class: far
 * from every ball, or deep inside one shrunk ball) provably have one label on all corners, so
 * skipping them drops no triangle. Placing vertices along their edges changes no incidence. */
#define _POSIX_C_SOURCE 200809L /* getrlimit */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "core/core.h"
#include "skin/skin_internal.h"
#include "skin/skin_map.h"

#define AXIS_BITS 20
#define AXIS_MAX ((uint64_t)1 << AXIS_BITS)

/* ---- the marching state ---- */

/* What the marcher keeps per grid point when the visited cubes' x-y extent is small (the usual
 * case): its label and the vertices on its 7 edges towards higher coordinates, in two planes
 * indexed by z parity. The cubes come sorted by z, and a cube of layer z only touches points of
 * planes z and z + 1, so a slot whose stamp z differs from the point's is stale (a finished
 * plane) and is reset on first use: no hashing, no clearing. */
typedef struct slab_point {
    uint32_t z;       /* the plane the slot holds, UINT32_MAX for none */
    uint32_t lab;     /* label(), LABEL_UNSET before the first evaluation */
    uint32_t vert[7]; /* vertex on the edge p -> p + dir (index dir - 1), UINT32_MAX for none */
} slab_point;

/* The largest x-y extent (in grid points) kept in slabs (2 x 36 MB); beyond it hash maps. */
#define SLAB_MAX_POINTS ((size_t)1 << 19)

typedef struct marcher {
    const fl_skin_function *g;
    double origin[3], h;
    slab_point *slab; /* 2 planes of dx * dy points from (xlo, ylo), or NULL: the maps below */
    uint64_t xlo, ylo;
    size_t dx, dy;
    u64map label; /* grid point -> label() */
    u64map vert;  /* grid edge (point << 3 | direction) -> vertex index */
    fl_vec xyz;   /* double[3] per vertex */
    fl_vec tri;   /* uint32_t[3] per triangle */
    size_t evaluations;
    uint32_t hint; /* the walk's start: the mixed cell of the previous evaluation */
} marcher;

static uint64_t pack(const uint64_t p[3])
{
    return (p[2] << (2 * AXIS_BITS)) | (p[1] << AXIS_BITS) | p[0];
}

static void grid_point(const marcher *m, const uint64_t p[3], double x[3])
{
    for (int c = 0; c < 3; c++)
        x[c] = m->origin[c] + m->h * (double)p[c];
}

/* The label of grid point p: bit 0 inside (G < 0), the bits above its mixed cell (LABEL_NO_CELL
 * when the walk found none); UINT32_MAX on allocation failure. */
#define LABEL_NO_CELL ((UINT32_MAX >> 1) - 1)
#define LABEL_UNSET UINT32_MAX

/* p's slot in the slabs, reset when it holds a finished plane. */
static slab_point *slab_at(marcher *m, const uint64_t p[3])
{
    slab_point *s = m->slab + (size_t)(p[2] & 1) * m->dx * m->dy +
                    (size_t)(p[1] - m->ylo) * m->dx + (size_t)(p[0] - m->xlo);
    if (s->z != (uint32_t)p[2]) {
        s->z = (uint32_t)p[2];
        s->lab = LABEL_UNSET;
        memset(s->vert, 0xff, sizeof s->vert);
    }
    return s;
}

static uint32_t evaluate_label(marcher *m, const uint64_t p[3])
{
    double x[3], val;
    grid_point(m, p, x);
    m->evaluations++;
    uint32_t c = skin_locate(m->g, x, &m->hint, &val);
    return (c < LABEL_NO_CELL ? c : LABEL_NO_CELL) << 1 | (val < 0);
}

static uint32_t label(marcher *m, const uint64_t p[3])
{
    if (m->slab) {
        slab_point *s = slab_at(m, p);
        if (s->lab == LABEL_UNSET) s->lab = evaluate_label(m, p);
        return s->lab;
    }
    uint64_t key = pack(p);
    size_t s = map_slot(&m->label, key);
    if (m->label.key[s] == key) return m->label.val[s];
    uint32_t lab = evaluate_label(m, p);
    return map_put(&m->label, key, lab) == SIZE_MAX ? UINT32_MAX : lab;
}

static uint32_t label_cell(uint32_t lab)
{
    return lab >> 1 == LABEL_NO_CELL ? SKIN_NO_CELL : lab >> 1;
}

/* The vertex on grid edge p -> p + dir (dir a nonzero 0/1 vector, bits x=1 y=2 z=4), placed by
 * skin_edge_root from the labels lp, lq of p and p + dir. UINT32_MAX on allocation failure. */
static uint32_t edge_vertex(marcher *m, const uint64_t p[3], unsigned dir, uint32_t lp,
                            uint32_t lq)
{
    uint64_t key = pack(p) << 3 | dir;
    uint32_t *slot = NULL;
    size_t s = 0;
    if (m->slab) {
        slot = &slab_at(m, p)->vert[dir - 1];
        if (*slot != UINT32_MAX) return *slot;
    } else {
        s = map_slot(&m->vert, key);
        if (m->vert.key[s] == key) return m->vert.val[s];
    }
    uint64_t q[3] = {p[0] + (dir & 1), p[1] + (dir >> 1 & 1), p[2] + (dir >> 2 & 1)};
    double a[3], b[3], x[3];
    int p_inside = lp & 1;
    grid_point(m, p_inside ? p : q, a);
    grid_point(m, p_inside ? q : p, b);
    skin_edge_root(m->g, a, b, label_cell(p_inside ? lp : lq), label_cell(p_inside ? lq : lp),
                   &m->hint, x, &m->evaluations);
    uint32_t v = (uint32_t)m->xyz.count;
    if (fl_vec_push(&m->xyz, x, 1)) return UINT32_MAX;
    if (slot) return *slot = v;
    return map_put(&m->vert, key, v) == SIZE_MAX ? UINT32_MAX : v;
}

/* Emits triangle (a, b, c) on edges whose doubled midpoints are ma, mb, mc (exact small
 * integers), oriented so its normal points along `outward` (outside minus inside corners):
 * exact, since the midpoint triangle of a grid tetrahedron is never flat. */
static int emit(marcher *m, uint32_t a, uint32_t b, uint32_t c, const double *ma, const double *mb,
                const double *mc, const double *outward)
{
    double u[3], v[3];
    for (int k = 0; k < 3; k++) {
        u[k] = mb[k] - ma[k];
        v[k] = mc[k] - ma[k];
    }
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double dot = n[0] * outward[0] + n[1] * outward[1] + n[2] * outward[2];
    uint32_t t[3] = {a, dot > 0 ? b : c, dot > 0 ? c : b};
    return fl_vec_push(&m->tri, t, 1);
}

typedef struct tet_corner {
    uint64_t p[3];
    double local[3]; /* corner offset inside the cube, 0 or 1 per axis */
    int in;
    uint32_t lab; /* label() */
} tet_corner;

/* The vertex on the edge between corners a and b (one inside, one outside) and its doubled
 * midpoint in cube coordinates. */
static uint32_t corner_edge(marcher *m, const tet_corner *a, const tet_corner *b, double mid[3])
{
    const tet_corner *lo = a, *hi = b;
    if (a->p[0] + a->p[1] + a->p[2] > b->p[0] + b->p[1] + b->p[2]) {
        lo = b;
        hi = a;
    }
    unsigned dir = 0;
    for (int c = 0; c < 3; c++) {
        dir |= (unsigned)(hi->p[c] - lo->p[c]) << c;
        mid[c] = a->local[c] + b->local[c];
    }
    return edge_vertex(m, lo->p, dir, lo->lab, hi->lab);
}

/* Marching tetrahedra on one tetrahedron: one triangle when one corner differs from the
 * other three, a quad (two triangles) when two are inside and two outside. */
static int march_tet(marcher *m, const tet_corner *c)
{
    int ins[4], outs[4], ni = 0, no = 0;
    for (int i = 0; i < 4; i++) {
        if (c[i].in)
            ins[ni++] = i;
        else
            outs[no++] = i;
    }
    if (ni == 0 || no == 0) return 0;
    double outward[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
        for (int i = 0; i < no; i++)
            outward[k] += c[outs[i]].local[k] * ni;
        for (int i = 0; i < ni; i++)
            outward[k] -= c[ins[i]].local[k] * no;
    }
    double mp[4][3];
    uint32_t v[4];
    if (ni == 1 || no == 1) {
        const int *lone = ni == 1 ? ins : outs, *rest = ni == 1 ? outs : ins;
        for (int i = 0; i < 3; i++)
            v[i] = corner_edge(m, &c[lone[0]], &c[rest[i]], mp[i]);
        if (v[0] == UINT32_MAX || v[1] == UINT32_MAX || v[2] == UINT32_MAX) return -1;
        return emit(m, v[0], v[1], v[2], mp[0], mp[1], mp[2], outward);
    }
    /* quad around the tetrahedron: a-c, a-d, b-d, b-c for inside a, b and outside c, d */
    v[0] = corner_edge(m, &c[ins[0]], &c[outs[0]], mp[0]);
    v[1] = corner_edge(m, &c[ins[0]], &c[outs[1]], mp[1]);
    v[2] = corner_edge(m, &c[ins[1]], &c[outs[1]], mp[2]);
    v[3] = corner_edge(m, &c[ins[1]], &c[outs[0]], mp[3]);
    for (int i = 0; i < 4; i++)
        if (v[i] == UINT32_MAX) return -1;
    if (emit(m, v[0], v[1], v[2], mp[0], mp[1], mp[2], outward)) return -1;
    return emit(m, v[0], v[2], v[3], mp[0], mp[2], mp[3], outward);
}

/* The six Kuhn tetrahedra of the cube at grid point p: corner 000, then one axis at a time in
 * the order of a permutation, to corner 111. */
static int march_cube(marcher *m, const uint64_t p[3])
{
    static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                   {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    uint32_t lab[8];
    int any_in = 0, any_out = 0;
    for (int b = 0; b < 8; b++) {
        uint64_t q[3] = {p[0] + (b & 1), p[1] + (b >> 1 & 1), p[2] + (b >> 2 & 1)};
        lab[b] = label(m, q);
        if (lab[b] == UINT32_MAX) return -1;
        any_in |= lab[b] & 1;
        any_out |= !(lab[b] & 1);
    }
    if (!any_in || !any_out) return 0;
    for (int t = 0; t < 6; t++) {
        tet_corner c[4];
        unsigned bits = 0;
        for (int i = 0; i < 4; i++) {
            if (i > 0) bits |= 1u << perm[t][i - 1];
            for (int k = 0; k < 3; k++) {
                c[i].local[k] = (double)(bits >> k & 1);
                c[i].p[k] = p[k] + (bits >> k & 1);
            }
            c[i].lab = lab[bits];
            c[i].in = lab[bits] & 1;
        }
        if (march_tet(m, c)) return -1;
    }
    return 0;
}

/* ---- the driver ---- */

static int cmp_u64(const void *pa, const void *pb)
{
    uint64_t a = *(const uint64_t *)pa, b = *(const uint64_t *)pb;
    return a < b ? -1 : a > b;
}

/* Margin of the cube culling, in cells (cube_class). */
#define CULL_MARGIN 1e-3

/* The cube range [lo, hi] of ball b's bounding box grown by the culling margin; its cube count. */
static double ball_cubes(const marcher *m, const double *b, uint64_t lo[3], uint64_t hi[3])
{
    double r = sqrt(b[3]) + CULL_MARGIN * m->h, count = 1;
    for (int c = 0; c < 3; c++) {
        lo[c] = (uint64_t)floor((b[c] - r - m->origin[c]) / m->h);
        hi[c] = (uint64_t)floor((b[c] + r - m->origin[c]) / m->h);
        count *= (double)(hi[c] - lo[c] + 1);
    }
    return count;
}

/* Which cubes the marcher needs (only cubes with an inside and an outside corner carry
 * triangles; skipping any other cube drops nothing and keeps the triangulation conforming):
 *  CUBE_FAR   the cube is farther than r + m from ball b's centre;
 *  CUBE_DEEP  all of the cube is within sqrt(t) r - m of it, inside the shrunk ball b^t, where
 *             G(y) <= |y - c|^2 - t w < 0: every corner is inside;
 *  CUBE_NEAR  neither.
 * A cube FAR from every positive ball lies outside their union, which contains body^t (§6.1),
 * and at distance delta >= m from body^t G >= delta^2 > 0 (G = (d - r')(d + r') for the nearest
 * shrunk ball of radius r' at distance d >= r' + delta): every corner is outside. The margin
 * m (1e-3 cells) puts both signs far above G's rounding. The corner coordinates are computed as
 * grid_point does, so the test sees the same points the labels do. */
enum { CUBE_FAR, CUBE_NEAR, CUBE_DEEP };
static int cube_class(const marcher *m, const double *b, double t, const uint64_t p[3])
{
    double near2 = 0, far2 = 0, mg = CULL_MARGIN * m->h, r = sqrt(b[3]);
    for (int c = 0; c < 3; c++) {
        double lo = m->origin[c] + m->h * (double)p[c] - b[c];
        double hi = m->origin[c] + m->h * (double)(p[c] + 1) - b[c];
        double nd = lo > 0 ? lo : hi < 0 ? -hi : 0, fd = fmax(fabs(lo), fabs(hi));
        near2 += nd * nd;
        far2 += fd * fd;
    }
    if (!(near2 <= (r + mg) * (r + mg))) return CUBE_FAR;
    double rs = sqrt(t) * r - mg;
    return rs > 0 && far2 < rs * rs ? CUBE_DEEP : CUBE_NEAR;
}

enum { BITMAP_MAX_BITS = 1 << 28 };

static int bit_get(const uint8_t *bits, size_t id)
{
    return bits[id >> 3] >> (id & 7) & 1;
}

static void bit_set(uint8_t *bits, size_t id)
{
    bits[id >> 3] |= (uint8_t)(1u << (id & 7));
}

/* collect_cubes through two bitmaps of the box of all positive balls (when it has at most
 * BITMAP_MAX_BITS cubes): near (some ball is not FAR) and deep (some ball is DEEP); the visited
 * cubes are near and not deep. Many overlapping balls (the eps-approximation's B*, 10^5 balls
 * on a torus) overcount their union by 100x, which the limit must not see. -1 when the box is
 * too large for the bitmaps. */
static int collect_bitmap(const marcher *m, const double *xyzw, size_t n, double t,
                          size_t max_cubes, fl_vec *cubes, fl_status *st, fl_error *err)
{
    uint64_t glo[3] = {UINT64_MAX, UINT64_MAX, UINT64_MAX}, ghi[3] = {0, 0, 0}, lo[3], hi[3];
    for (size_t i = 0; i < n; i++) {
        if (!(xyzw[4 * i + 3] > 0)) continue;
        ball_cubes(m, xyzw + 4 * i, lo, hi);
        for (int c = 0; c < 3; c++) {
            glo[c] = lo[c] < glo[c] ? lo[c] : glo[c];
            ghi[c] = hi[c] > ghi[c] ? hi[c] : ghi[c];
        }
    }
    if (glo[0] > ghi[0]) return 0; /* no positive ball: caller's loop finds no cube either */
    double cells = 1;
    uint64_t d[3];
    for (int c = 0; c < 3; c++) {
        d[c] = ghi[c] - glo[c] + 1;
        cells *= (double)d[c];
    }
    if (cells > BITMAP_MAX_BITS) return -1;
    uint8_t *near = calloc((size_t)cells / 8 + 1, 1), *deep = calloc((size_t)cells / 8 + 1, 1);
    if (!near || !deep) {
        free(near);
        free(deep);
        return -1;
    }
    for (size_t i = 0; i < n; i++) {
        if (!(xyzw[4 * i + 3] > 0)) continue;
        ball_cubes(m, xyzw + 4 * i, lo, hi);
        uint64_t p[3];
        for (p[2] = lo[2]; p[2] <= hi[2]; p[2]++)
            for (p[1] = lo[1]; p[1] <= hi[1]; p[1]++)
                for (p[0] = lo[0]; p[0] <= hi[0]; p[0]++) {
                    int cls = cube_class(m, xyzw + 4 * i, t, p);
                    if (cls == CUBE_FAR) continue;
                    size_t id = (size_t)(((p[2] - glo[2]) * d[1] + (p[1] - glo[1])) * d[0] +
                                         (p[0] - glo[0]));
                    bit_set(cls == CUBE_DEEP ? deep : near, id);
                }
    }
    size_t unique = 0, all = (size_t)cells;
    for (size_t id = 0; id < all; id++)
        unique += bit_get(near, id) && !bit_get(deep, id);
    *st = FL_OK;
    if (unique > max_cubes)
        *st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                      "skin: the grid would visit %zu cubes (more than %zu); choose a larger "
                      "cell than %g",
                      unique, max_cubes, m->h);
    /* z-major scan: the keys come out sorted (pack puts z in the high bits) */
    for (size_t id = 0; id < all && !*st; id++) {
        if (!bit_get(near, id) || bit_get(deep, id)) continue;
        uint64_t p[3] = {id % d[0] + glo[0], id / d[0] % d[1] + glo[1], id / d[0] / d[1] + glo[2]};
        uint64_t key = pack(p);
        if (fl_vec_push(cubes, &key, 1))
            *st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    }
    free(near);
    free(deep);
    return 0;
}

/* The cubes to visit, sorted and unique (keys of their lowest corner). Fails with FL_ERR_INPUT
 * when they are more than max_cubes (without the bitmaps: when the balls' boxes hold more than
 * max_cubes cubes in total; that path visits every cube some ball does not find FAR). */
static fl_status collect_cubes(const marcher *m, const double *xyzw, size_t n, double t,
                               size_t max_cubes, fl_vec *cubes, fl_error *err)
{
    fl_status bst = FL_OK;
    if (collect_bitmap(m, xyzw, n, t, max_cubes, cubes, &bst, err) == 0) return bst;
    for (int pass = 0; pass < 2; pass++) {
        double total = 0;
        for (size_t i = 0; i < n; i++) {
            const double *b = xyzw + 4 * i;
            if (!(b[3] > 0)) continue;
            uint64_t lo[3], hi[3];
            total += ball_cubes(m, b, lo, hi);
            if (pass == 0) continue;
            uint64_t p[3];
            for (p[2] = lo[2]; p[2] <= hi[2]; p[2]++)
                for (p[1] = lo[1]; p[1] <= hi[1]; p[1]++)
                    for (p[0] = lo[0]; p[0] <= hi[0]; p[0]++) {
                        uint64_t key = pack(p);
                        if (cube_class(m, b, t, p) != CUBE_FAR && fl_vec_push(cubes, &key, 1))
                            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
                    }
        }
        if (pass == 0 && total > (double)max_cubes)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "skin: the grid would visit %.3g cubes (more than %zu); choose a "
                           "larger cell than %g",
                           total, max_cubes, m->h);
    }
    qsort(cubes->data, cubes->count, sizeof(uint64_t), cmp_u64);
    uint64_t *k = cubes->data;
    size_t u = 0;
    for (size_t i = 0; i < cubes->count; i++)
        if (u == 0 || k[i] != k[u - 1]) k[u++] = k[i];
    cubes->count = u;
    return FL_OK;
}

/* The default spacing: a quarter of the smallest shrunk radius, smaller where the skin has a
 * thin neck. Two overlapping balls (an edge of the regular triangulation whose orthogonal
 * weight w is negative and whose focus lies between them) give a neck of waist radius
 * sqrt(-t w) in the edge's mixed cell (q orthogonal, p = 0 in the quadric); the grid must
 * straddle it with about two cells or marching tetrahedra can cut it. Down to 1/4 of the
 * first value, so one near-tangent pair cannot blow the grid up; thinner necks need --cell. */
static double default_cell(const fl_skin_function *g, double t, double rmin)
{
    double h = 0.25 * sqrt(t) * rmin, floor_h = 0.25 * h;
    for (size_t i = 0; i < g->simplex_count; i++) {
        const skin_simplex *s = &g->simplex[i];
        if (s->k != 1 || s->mu_f[0] < 0 || s->mu_f[0] > 1) continue;
        double a[3], e[3][3], f[3];
        skin_frame(g->balls, s, a, e);
        skin_focus(s, a, e, f);
        double w = skin_weight(g->balls, s, a, f);
        if (!(w < 0)) continue;
        double waist = sqrt(-t * w);
        if (waist < h) h = fmax(waist, floor_h);
    }
    return h;
}

/* Grid spacing and origin: the box of the positive balls with one spare cell around it. */
static fl_status setup_grid(marcher *m, const double *xyzw, size_t n, double t, double cell,
                            fl_error *err)
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    double rmin = HUGE_VAL;
    for (size_t i = 0; i < n; i++) {
        const double *b = xyzw + 4 * i;
        if (!(b[3] > 0)) continue;
        double r = sqrt(b[3]);
        rmin = fmin(rmin, r);
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], b[c] - r);
            hi[c] = fmax(hi[c], b[c] + r);
        }
    }
    m->h = cell > 0 ? cell : default_cell(m->g, t, rmin);
    for (int c = 0; c < 3; c++) {
        /* an odd fraction of a cell off the box keeps grid points off the special positions of
         * hand-made inputs (centres on round coordinates), where the skin would pass through
         * a grid point and several edge vertices would coincide */
        m->origin[c] = lo[c] - (1 + 0.3183098861837907 * (c + 1) / 3) * m->h;
        if (!((hi[c] - lo[c]) / m->h + 4 < (double)(AXIS_MAX - 2)))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "skin: cell %g gives more than 2^20 grid cells along an axis", m->h);
    }
    return FL_OK;
}

static fl_status march_all(marcher *m, const fl_vec *cubes, const fl_skin_options *o, fl_error *err)
{
    const uint64_t *k = cubes->data;
    uint64_t hi[2] = {0, 0};
    m->xlo = m->ylo = AXIS_MAX;
    for (size_t i = 0; i < cubes->count; i++) {
        uint64_t x = k[i] & (AXIS_MAX - 1), y = k[i] >> AXIS_BITS & (AXIS_MAX - 1);
        m->xlo = x < m->xlo ? x : m->xlo;
        m->ylo = y < m->ylo ? y : m->ylo;
        hi[0] = x > hi[0] ? x : hi[0];
        hi[1] = y > hi[1] ? y : hi[1];
    }
    /* the output's usual size (about 0.65 vertices and 1.3 triangles a visited cube): growing
     * the vectors copies them and faults their pages in again */
    if (fl_vec_reserve(&m->xyz, cubes->count / 3 * 2 + 64) ||
        fl_vec_reserve(&m->tri, cubes->count / 3 * 4 + 64))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    m->dx = cubes->count ? (size_t)(hi[0] - m->xlo + 2) : 0; /* corners: one more than cubes */
    m->dy = cubes->count ? (size_t)(hi[1] - m->ylo + 2) : 0;
    if (m->dx && m->dx * m->dy <= SLAB_MAX_POINTS) {
        m->slab = fl_alloc_array(2 * m->dx * m->dy, sizeof(slab_point));
        if (!m->slab) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
        memset(m->slab, 0xff, 2 * m->dx * m->dy * sizeof(slab_point));
    } else {
        /* sized for the usual counts (about 1.3 grid points and 0.65 vertices a visited
         * cube), so the maps seldom grow */
        size_t est = cubes->count + cubes->count / 2 + 64;
        if (map_init(&m->label, est) || map_init(&m->vert, est / 2))
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    }
    for (size_t i = 0; i < cubes->count; i++) {
        if ((i & 4095) == 0 &&
            fl_progress(o->progress, o->progress_user, "skin", (double)i / (double)cubes->count))
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
        uint64_t p[3] = {k[i] & (AXIS_MAX - 1), k[i] >> AXIS_BITS & (AXIS_MAX - 1),
                         k[i] >> (2 * AXIS_BITS)};
        if (march_cube(m, p)) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
        if (m->xyz.count >= UINT32_MAX - 8)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: more than 2^32 vertices");
    }
    return FL_OK;
}

/* The refinement of the boxes for the graded grid: every vertex of m in a box becomes a point
 * wanting cells of the box's h, one a cube of side h. The grid is refined along the mesh's
 * surface in the box, not through its volume (a box of 16 faces' size at h a face, on random
 * 100-ball sets: 554 k vertices from 33 k, 41 s; along the surface: see docs/skin.md round 17). */
static fl_status surface_points(const fl_mesh *m, const fl_vec *boxes, size_t first, fl_vec *sizes,
                                fl_error *err)
{
    u64map seen;
    if (map_init(&seen, 1024)) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    fl_status st = FL_OK;
    for (size_t v = 0; v < m->vertex_count && !st; v++) {
        const double *x = m->xyz + 3 * v;
        for (size_t i = first; i < boxes->count; i++) {
            const skin_box *b = (const skin_box *)boxes->data + i;
            if (!(x[0] >= b->lo[0] && x[0] <= b->hi[0] && x[1] >= b->lo[1] && x[1] <= b->hi[1] &&
                  x[2] >= b->lo[2] && x[2] <= b->hi[2]))
                continue;
            uint64_t key, hb;
            memcpy(&hb, &b->h, sizeof hb);
            key = mix64(hb);
            for (int c = 0; c < 3; c++) { /* the cube's index, clamped into int64_t */
                double q = fmin(fmax(floor(x[c] / b->h), -9e18), 9e18);
                key = mix64(key ^ (uint64_t)(int64_t)q);
            }
            if (key == UINT64_MAX) key = 0;
            size_t s = map_slot(&seen, key);
            if (seen.key[s] == key) continue;
            skin_box p = {{x[0], x[1], x[2]}, {x[0], x[1], x[2]}, b->h};
            if (map_put(&seen, key, 0) == SIZE_MAX || fl_vec_push(sizes, &p, 1))
                st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
            break;
        }
    }
    map_free(&seen);
    return st;
}

/* fl_skin_options.repair: while the mesh's Euler characteristic or number of components
 * differs from the skin's (2 chi and b0 + b2 of the union, fl_balls_union_betti), box its local
 * handles and extra small components (skin_mesh_defects), refine the grid along the mesh in
 * the boxes (surface_points) and mesh again, at most o->repair times. The grid away from the
 * boxes stays as it was (position-hashed corner weights, skin_graded.c). Stops early when no
 * box is found or the grid would exceed its leaf cap (the last mesh is kept). gs->repairs
 * counts the meshes redone. betti: the union's Betti numbers when the caller has them (NULL:
 * computed here). */
static fl_status repair(const fl_skin_function *g, const double *xyzw, size_t n,
                        const fl_skin_options *o, const long long *betti, fl_vec *sizes,
                        fl_mesh *out, fl_skin_stats *gs, fl_error *err)
{
    long long b[3];
    fl_status st = FL_OK;
    if (betti)
        memcpy(b, betti, sizeof b);
    else
        st = fl_balls_union_betti(xyzw, n, b, err);
    if (st != FL_OK) return st;
    long long euler_expected = 2 * (b[0] - b[1] + b[2]), comps_expected = b[0] + b[2];
    fl_vec boxes;
    fl_vec_init(&boxes, sizeof(skin_box));
    for (int r = 0; r < o->repair && !st; r++) {
        long long euler = (long long)out->vertex_count - (long long)out->triangle_count / 2;
        long long comps = skin_mesh_components(out);
        if (comps < 0) {
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
            break;
        }
        if (euler == euler_expected && comps == comps_expected) break;
        /* the skin's genus in all is b1 (its chi is 2 chi(union), its components b0 + b2):
         * too much genus is a false handle, too many components a false bubble; the other
         * errors (a missed cavity or component, a closed tunnel) have nothing to box */
        int handles = 2 * comps - euler > 2 * b[1];
        size_t before = boxes.count;
        st = skin_mesh_defects(out, xyzw, n, handles, comps - comps_expected, &boxes, err);
        if (st == FL_ERR_INPUT) { /* a mesh too large to inspect: keep it */
            fl_error_clear(err);
            st = FL_OK;
            break;
        }
        if (st != FL_OK || boxes.count == before) break;
        st = surface_points(out, &boxes, before, sizes, err);
        if (st != FL_OK) break;
        fl_mesh next = {0};
        fl_skin_stats ns = {0};
        st = skin_graded_mesh(g, xyzw, n, o, sizes, &next, &ns, err);
        if (st == FL_ERR_INPUT) { /* over the leaf cap: keep the last mesh */
            fl_error_clear(err);
            st = FL_OK;
            break;
        }
        if (st != FL_OK) break;
        fl_mesh_free(out);
        *out = next;
        *gs = ns;
        gs->repairs = (unsigned)(r + 1);
    }
    fl_vec_free(&boxes);
    return st;
}

/* The graded path (skin_graded.c) with the checks of the uniform one. */
static fl_status graded(const double *xyzw, size_t n, const fl_skin_options *o, fl_mesh *out,
                        fl_skin_stats *stats, int offsets, const long long *betti, fl_error *err)
{
    fl_skin_function *g = NULL;
    fl_status st = skin_function_new_mesher(xyzw, n, o->t, &g, err);
    if (st != FL_OK) return st;
    fl_skin_options go = *o;
    double rmax = 0, cmax = 0;
    for (size_t i = 0; i < n; i++) {
        if (xyzw[4 * i + 3] > 0) rmax = fmax(rmax, sqrt(xyzw[4 * i + 3]));
        for (int c = 0; c < 3; c++)
            cmax = fmax(cmax, fabs(xyzw[4 * i + c]));
    }
    if (go.cell == 0) go.cell = go.grade * sqrt(go.t) * rmax;
    fl_skin_stats gs = {0};
    fl_vec sizes; /* skin_box, the points of local refinement */
    fl_vec_init(&sizes, sizeof(skin_box));
    st = skin_graded_mesh(g, xyzw, n, &go, &sizes, out, &gs, err);
    if (!st && go.repair > 0) st = repair(g, xyzw, n, &go, betti, &sizes, out, &gs, err);
    fl_vec_free(&sizes);
    if (st) fl_mesh_free(out);
    /* leaves below the coordinates' resolution make points coincide (see fl_skin_mesh) */
    if (!st && !(gs.cell >= 1e-12 * cmax)) {
        fl_mesh_free(out);
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "skin: graded cell %g is below the resolution of the coordinates (a ball "
                     "too small for its position)",
                     gs.cell);
    }
    if (!st && stats) {
        *stats = gs;
        if (offsets)
            stats->max_vertex_offset =
                skin_vertex_offset(g, out->xyz, out->vertex_count, gs.cell, &stats->evaluations);
    }
    fl_skin_function_free(g);
    if (st) memset(out, 0, sizeof *out);
    return st;
}

/* The graded grid's default leaf cap: the process's address-space limit (RLIMIT_AS, what the
 * CLI's --max-memory sets; src/cli/memlimit.c) over SKIN_GRADED_LEAF_BYTES, at least
 * 3e6 (the cap before round 13), and 3e6 without a limit. Measured on cube.off's B* (4293
 * balls, eps 0.5) through fl_skin_mesh at grades 2, 1, 0.5: 94 193, 300 518 and 1 269 976
 * leaves, peak RSS 79, 182 and 623 MB, i.e. 497 and 466 bytes per added leaf (the octree's
 * corners, their Delaunay tetrahedralization, labels and the output; docs/skin.md round 13).
 * The limit is an upper bound: the skin function and the input share it, and where they leave
 * less the allocations fail cleanly (FL_ERR_NOMEM) under the same limit. The npm bunny at
 * grade 4 (6 719 553 leaves) needs about 3.4 GB of it, so --max-memory 14G allows it. */
#define SKIN_GRADED_LEAF_BYTES 512
#define SKIN_GRADED_LEAF_MIN 3000000
static size_t graded_leaf_cap(void)
{
    struct rlimit r;
    if (getrlimit(RLIMIT_AS, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return SKIN_GRADED_LEAF_MIN;
    double cap = (double)r.rlim_cur / SKIN_GRADED_LEAF_BYTES;
    if (cap < SKIN_GRADED_LEAF_MIN) return SKIN_GRADED_LEAF_MIN;
    return cap > 4e9 ? (size_t)4e9 : (size_t)cap; /* corners are numbered by uint32_t */
}

fl_status fl_skin_mesh(const double *xyzw, size_t n, const fl_skin_options *opt, fl_mesh *out,
                       fl_skin_stats *stats, fl_error *err)
{
    return skin_mesh_run(xyzw, n, opt, out, stats, stats != NULL, NULL, err);
}

fl_status skin_mesh_run(const double *xyzw, size_t n, const fl_skin_options *opt, fl_mesh *out,
                        fl_skin_stats *stats, int offsets, const long long *betti, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "skin: NULL output");
    memset(out, 0, sizeof *out);
    if (stats) memset(stats, 0, sizeof *stats);
    fl_skin_options o = {0};
    if (opt) o = *opt;
    if (o.t == 0) o.t = 0.5;
    if (o.max_cubes == 0) o.max_cubes = o.grade > 0 ? graded_leaf_cap() : 50000000;
    if (!(o.cell >= 0) || !isfinite(o.cell) || !(o.grade >= 0) || !isfinite(o.grade) ||
        o.repair < 0)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "skin: cell and grade must be finite numbers >= 0, repair >= 0");
    if (o.grade > 0) return graded(xyzw, n, &o, out, stats, offsets, betti, err);
    marcher m;
    memset(&m, 0, sizeof m);
    fl_vec_init(&m.xyz, 3 * sizeof(double));
    fl_vec_init(&m.tri, 3 * sizeof(uint32_t));
    fl_vec cubes;
    fl_vec_init(&cubes, sizeof(uint64_t));
    fl_skin_function *g = NULL;
    fl_status st = skin_function_new_mesher(xyzw, n, o.t, &g, err);
    m.g = g;
    if (!st) st = setup_grid(&m, xyzw, n, o.t, o.cell, err);
    /* A spacing below the coordinates' resolution (a ball of radius 1e-75 at x = -8) makes grid
     * points coincide after rounding, and the mesh came out open (16 boundary edges; found by
     * fuzz/fuzz_skin.c). Refuse it. */
    for (size_t i = 0; !st && i < n; i++)
        for (int c = 0; !st && c < 3; c++)
            if (m.h < 1e-12 * fabs(xyzw[4 * i + c]))
                st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                             "skin: grid spacing %g is below the resolution of coordinate %g "
                             "(a ball too small for its position)",
                             m.h, xyzw[4 * i + c]);
    if (!st) st = collect_cubes(&m, xyzw, n, o.t, o.max_cubes, &cubes, err);
    if (!st) st = march_all(&m, &cubes, &o, err);
    if (!st && m.tri.count == 0)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "skin: no grid point lies inside the skin; choose a cell below %g", m.h);
    if (!st && stats) {
        stats->cell = m.h;
        stats->cubes = cubes.count;
        stats->evaluations = m.evaluations;
        if (offsets)
            stats->max_vertex_offset =
                skin_vertex_offset(g, m.xyz.data, m.xyz.count, m.h, &stats->evaluations);
    }
    if (!st) skin_hand_over(&m.xyz, &m.tri, out);
    fl_vec_free(&m.xyz);
    fl_vec_free(&m.tri);
    fl_vec_free(&cubes);
    map_free(&m.label);
    map_free(&m.vert);
    free(m.slab);
    fl_skin_function_free(g);
    return st;
}

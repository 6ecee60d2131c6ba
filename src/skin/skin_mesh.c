/* Triangulating skin^t(B): marching tetrahedra on the Kuhn subdivision of a cubic grid, with
 * every vertex moved onto the skin by bisection of the skin function along its grid edge.
 *
 * Why this is a closed 2-manifold for every input: the six Kuhn tetrahedra of every cube (the
 * paths from corner 000 to 111) fit across cube faces, so together they form one conforming
 * triangulation of the visited cubes. Each grid point gets one label, inside (G < 0) or not,
 * so the surface is the boundary of the union of "inside" regions of the piecewise-linear
 * interpolant at a regular value; it has no boundary and every edge lies in two triangles.
 * Cubes outside every ball's bounding box are not visited: their corners lie outside the
 * union of balls, which contains body^t(B) (body^t is inside body^1 = union B, §6.1), so no
 * such cube has an inside corner and skipping it drops no triangle. Bisection moves vertices
 * along their edges without changing any incidence. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "skin/skin_internal.h"
#include "skin/skin_map.h"

#define AXIS_BITS 20
#define AXIS_MAX ((uint64_t)1 << AXIS_BITS)

/* ---- the marching state ---- */

typedef struct marcher {
    const fl_skin_function *g;
    double origin[3], h;
    u64map label; /* grid point -> 1 inside, 0 outside */
    u64map vert;  /* grid edge (point << 3 | direction) -> vertex index */
    fl_vec xyz;   /* double[3] per vertex */
    fl_vec tri;   /* uint32_t[3] per triangle */
    size_t evaluations;
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

static double eval(marcher *m, const double x[3])
{
    m->evaluations++;
    return fl_skin_function_value(m->g, x);
}

/* 1 when grid point p is inside the skin body, 0 outside, -1 on allocation failure. */
static int label(marcher *m, const uint64_t p[3])
{
    uint64_t key = pack(p);
    size_t s = map_slot(&m->label, key);
    if (m->label.key[s] == key) return (int)m->label.val[s];
    double x[3];
    grid_point(m, p, x);
    int in = eval(m, x) < 0;
    return map_put(&m->label, key, (uint32_t)in) == SIZE_MAX ? -1 : in;
}

/* A zero of G on the segment a -> b with G(a) < 0 <= G(b), written to x: the Illinois variant
 * of regula falsi (G is smooth along the segment, so it converges superlinearly) with a
 * bisection step whenever a step shrinks the bracket by less than half; it stops when the
 * bracket no longer shrinks, so x is within a rounding error of the skin. Adds the evaluations
 * of G to *evaluations. Shared by both meshers (skin_internal.h). */
void skin_edge_root(const fl_skin_function *g, const double a[3], const double b[3], double x[3],
                    size_t *evaluations)
{
    /* parameter s in [lo, hi] along a -> b; G(lo) < 0 <= G(hi) */
    double lo = 0, hi = 1, glo = fl_skin_function_value(g, a), ghi = fl_skin_function_value(g, b);
    size_t ev = 2;
    int side = 0;
    for (int it = 0; it < 200 && glo < 0 && ghi > 0; it++) {
        double width = hi - lo;
        double s_new = lo + (hi - lo) * (-glo / (ghi - glo));
        if (!(s_new > lo && s_new < hi)) s_new = 0.5 * (lo + hi);
        for (int c = 0; c < 3; c++)
            x[c] = a[c] + s_new * (b[c] - a[c]);
        double gx = fl_skin_function_value(g, x);
        ev++;
        if (gx < 0) {
            lo = s_new;
            glo = gx;
            if (side == -1) ghi *= 0.5; /* Illinois: the stale end would stall regula falsi */
            side = -1;
        } else {
            hi = s_new;
            ghi = gx;
            if (side == 1) glo *= 0.5;
            side = 1;
        }
        if (hi - lo > 0.5 * width) { /* slow step: bisect once */
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            for (int c = 0; c < 3; c++)
                x[c] = a[c] + mid * (b[c] - a[c]);
            double gm = fl_skin_function_value(g, x);
            ev++;
            if (gm < 0) {
                lo = mid;
                glo = gm;
            } else {
                hi = mid;
                ghi = gm;
            }
            side = 0;
        }
        if (!(hi - lo > 4 * DBL_EPSILON)) break;
    }
    /* the end with the smaller |G| (the halved Illinois values are not G: re-evaluate) */
    double xl[3], xh[3];
    for (int c = 0; c < 3; c++) {
        xl[c] = a[c] + lo * (b[c] - a[c]);
        xh[c] = a[c] + hi * (b[c] - a[c]);
    }
    double gl = fabs(fl_skin_function_value(g, xl)), gh = fabs(fl_skin_function_value(g, xh));
    *evaluations += ev + 2;
    memcpy(x, gl <= gh ? xl : xh, sizeof(xl));
}

/* The vertex on grid edge p -> p + dir (dir a nonzero 0/1 vector, bits x=1 y=2 z=4), placed by
 * skin_edge_root. Returns UINT32_MAX on allocation failure. */
static uint32_t edge_vertex(marcher *m, const uint64_t p[3], unsigned dir, int p_inside)
{
    uint64_t key = pack(p) << 3 | dir;
    size_t s = map_slot(&m->vert, key);
    if (m->vert.key[s] == key) return m->vert.val[s];
    uint64_t q[3] = {p[0] + (dir & 1), p[1] + (dir >> 1 & 1), p[2] + (dir >> 2 & 1)};
    double a[3], b[3], x[3];
    grid_point(m, p_inside ? p : q, a);
    grid_point(m, p_inside ? q : p, b);
    skin_edge_root(m->g, a, b, x, &m->evaluations);
    uint32_t v = (uint32_t)m->xyz.count;
    if (fl_vec_push(&m->xyz, x, 1)) return UINT32_MAX;
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
    return edge_vertex(m, lo->p, dir, lo->in);
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
    int lab[8], any_in = 0, any_out = 0;
    for (int b = 0; b < 8; b++) {
        uint64_t q[3] = {p[0] + (b & 1), p[1] + (b >> 1 & 1), p[2] + (b >> 2 & 1)};
        lab[b] = label(m, q);
        if (lab[b] < 0) return -1;
        any_in |= lab[b];
        any_out |= !lab[b];
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
            c[i].in = lab[bits];
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

/* The cube range [lo, hi] of ball b's bounding box; its cube count. */
static double ball_cubes(const marcher *m, const double *b, uint64_t lo[3], uint64_t hi[3])
{
    double r = sqrt(b[3]), count = 1;
    for (int c = 0; c < 3; c++) {
        lo[c] = (uint64_t)floor((b[c] - r - m->origin[c]) / m->h);
        hi[c] = (uint64_t)floor((b[c] + r - m->origin[c]) / m->h);
        count *= (double)(hi[c] - lo[c] + 1);
    }
    return count;
}

enum { BITMAP_MAX_BITS = 1 << 28 };

/* collect_cubes through a bitmap of the box of all positive balls (when it has at most
 * BITMAP_MAX_BITS cubes): many overlapping balls (the eps-approximation's B*, 10^5 balls on a
 * torus) overcount their union by 100x, which the limit must not see. -1 when the box is too
 * large for the bitmap. */
static int collect_bitmap(const marcher *m, const double *xyzw, size_t n, size_t max_cubes,
                          fl_vec *cubes, fl_status *st, fl_error *err)
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
    uint8_t *bits = calloc((size_t)cells / 8 + 1, 1);
    if (!bits) return -1;
    size_t unique = 0;
    for (size_t i = 0; i < n; i++) {
        if (!(xyzw[4 * i + 3] > 0)) continue;
        ball_cubes(m, xyzw + 4 * i, lo, hi);
        for (uint64_t z = lo[2]; z <= hi[2]; z++)
            for (uint64_t y = lo[1]; y <= hi[1]; y++)
                for (uint64_t x = lo[0]; x <= hi[0]; x++) {
                    size_t id =
                        (size_t)(((z - glo[2]) * d[1] + (y - glo[1])) * d[0] + (x - glo[0]));
                    unique += !(bits[id >> 3] & (1u << (id & 7)));
                    bits[id >> 3] |= (uint8_t)(1u << (id & 7));
                }
    }
    *st = FL_OK;
    if (unique > max_cubes)
        *st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                      "skin: the grid would visit %zu cubes (more than %zu); choose a larger "
                      "cell than %g",
                      unique, max_cubes, m->h);
    /* z-major scan: the keys come out sorted (pack puts z in the high bits) */
    for (uint64_t z = 0; z < d[2] && !*st; z++)
        for (uint64_t y = 0; y < d[1] && !*st; y++)
            for (uint64_t x = 0; x < d[0]; x++) {
                size_t id = (size_t)((z * d[1] + y) * d[0] + x);
                if (!(bits[id >> 3] & (1u << (id & 7)))) continue;
                uint64_t p[3] = {x + glo[0], y + glo[1], z + glo[2]};
                uint64_t key = pack(p);
                if (fl_vec_push(cubes, &key, 1)) {
                    *st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
                    break;
                }
            }
    free(bits);
    return 0;
}

/* The cubes meeting some positive ball's bounding box, sorted and unique (keys of their lowest
 * corner). Fails with FL_ERR_INPUT when they are more than max_cubes (without the bitmap: when
 * the boxes hold more than max_cubes cubes in total). */
static fl_status collect_cubes(const marcher *m, const double *xyzw, size_t n, size_t max_cubes,
                               fl_vec *cubes, fl_error *err)
{
    fl_status bst = FL_OK;
    if (collect_bitmap(m, xyzw, n, max_cubes, cubes, &bst, err) == 0) return bst;
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
                        if (fl_vec_push(cubes, &key, 1))
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
        if (s->k != 1 || !(s->w < 0) || s->mu_f[0] < 0 || s->mu_f[0] > 1) continue;
        double waist = sqrt(-t * s->w);
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

/* max over the vertices of |G(v)| / |grad G(v)| (central differences at step 1e-5 h). */
static double vertex_offset(marcher *m, const double *x, size_t count, double h)
{
    double worst = 0, d = 1e-5 * h;
    for (size_t i = 0; i < count; i++) {
        const double *v = x + 3 * i;
        double g2 = 0;
        for (int c = 0; c < 3; c++) {
            double a[3] = {v[0], v[1], v[2]}, b[3] = {v[0], v[1], v[2]};
            a[c] += d;
            b[c] -= d;
            double gc = (eval(m, a) - eval(m, b)) / (2 * d);
            g2 += gc * gc;
        }
        double off = fabs(eval(m, v)) / sqrt(g2);
        if (!(off <= worst)) worst = off;
    }
    return worst;
}

static fl_status march_all(marcher *m, const fl_vec *cubes, const fl_skin_options *o, fl_error *err)
{
    const uint64_t *k = cubes->data;
    size_t est = cubes->count / 4 + 64;
    if (map_init(&m->label, est) || map_init(&m->vert, est))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
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

/* The graded path (skin_graded.c) with the checks of the uniform one. */
static fl_status graded(const double *xyzw, size_t n, const fl_skin_options *o, fl_mesh *out,
                        fl_skin_stats *stats, fl_error *err)
{
    fl_skin_function *g = NULL;
    fl_status st = fl_skin_function_new(xyzw, n, o->t, &g, err);
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
    st = skin_graded_mesh(g, xyzw, n, &go, out, &gs, err);
    /* leaves below the coordinates' resolution make points coincide (see fl_skin_mesh) */
    if (!st && !(gs.cell >= 1e-12 * cmax)) {
        fl_mesh_free(out);
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "skin: graded cell %g is below the resolution of the coordinates (a ball "
                     "too small for its position)",
                     gs.cell);
    }
    if (!st && stats) {
        marcher m;
        memset(&m, 0, sizeof m);
        m.g = g;
        *stats = gs;
        stats->max_vertex_offset = vertex_offset(&m, out->xyz, out->vertex_count, gs.cell);
        stats->evaluations += m.evaluations;
    }
    fl_skin_function_free(g);
    if (st) memset(out, 0, sizeof *out);
    return st;
}

fl_status fl_skin_mesh(const double *xyzw, size_t n, const fl_skin_options *opt, fl_mesh *out,
                       fl_skin_stats *stats, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "skin: NULL output");
    memset(out, 0, sizeof *out);
    if (stats) memset(stats, 0, sizeof *stats);
    fl_skin_options o = {0};
    if (opt) o = *opt;
    if (o.t == 0) o.t = 0.5;
    if (o.max_cubes == 0) o.max_cubes = o.grade > 0 ? 3000000 : 50000000;
    if (!(o.cell >= 0) || !isfinite(o.cell) || !(o.grade >= 0) || !isfinite(o.grade))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "skin: cell and grade must be finite numbers >= 0");
    if (o.grade > 0) return graded(xyzw, n, &o, out, stats, err);
    marcher m;
    memset(&m, 0, sizeof m);
    fl_vec_init(&m.xyz, 3 * sizeof(double));
    fl_vec_init(&m.tri, 3 * sizeof(uint32_t));
    fl_vec cubes;
    fl_vec_init(&cubes, sizeof(uint64_t));
    fl_skin_function *g = NULL;
    fl_status st = fl_skin_function_new(xyzw, n, o.t, &g, err);
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
    if (!st) st = collect_cubes(&m, xyzw, n, o.max_cubes, &cubes, err);
    if (!st) st = march_all(&m, &cubes, &o, err);
    if (!st && m.tri.count == 0)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "skin: no grid point lies inside the skin; choose a cell below %g", m.h);
    if (!st && stats) {
        stats->cell = m.h;
        stats->cubes = cubes.count;
        stats->max_vertex_offset = vertex_offset(&m, m.xyz.data, m.xyz.count, m.h);
        stats->evaluations = m.evaluations;
    }
    if (!st) {
        out->vertex_count = m.xyz.count;
        out->triangle_count = m.tri.count;
        out->xyz = fl_vec_release(&m.xyz);
        out->tri = fl_vec_release(&m.tri);
    }
    fl_vec_free(&m.xyz);
    fl_vec_free(&m.tri);
    fl_vec_free(&cubes);
    map_free(&m.label);
    map_free(&m.vert);
    fl_skin_function_free(g);
    return st;
}

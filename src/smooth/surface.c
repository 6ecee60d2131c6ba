/* Cubic Bézier triangle surfaces interpolating the vertices and normals of a closed mesh:
 * the macro patches of thesis §9.6 steps 1-3 and the cubic three-split of steps 4-6. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smooth/smooth_internal.h"

/* Position of b_ijk (k = n - i - j) in a degree-n net listed by i descending, then j
 * descending: b300 b210 b201 b120 b111 b102 b030 b021 b012 b003 for n = 3. */
static int net_index(int n, int i, int j)
{
    return (n - i) * (n - i + 1) / 2 + (n - i - j);
}

void fl_g1_patch_eval(const double *ctrl, double u, double v, double w, double point[3],
                      double normal[3])
{
    double a[10][3], b[10][3];
    memcpy(a, ctrl, sizeof a);
    for (int n = 3; n > 1; n--) { /* de Casteljau: degree n -> n - 1 */
        for (int i = 0; i < n; i++)
            for (int j = 0; i + j < n; j++)
                for (int d = 0; d < 3; d++)
                    b[net_index(n - 1, i, j)][d] = u * a[net_index(n, i + 1, j)][d] +
                                                   v * a[net_index(n, i, j + 1)][d] +
                                                   w * a[net_index(n, i, j)][d];
        memcpy(a, b, sizeof a);
    }
    /* a[0] = b100, a[1] = b010, a[2] = b001 of the linear stage: the tangent plane there. */
    if (point)
        for (int d = 0; d < 3; d++)
            point[d] = u * a[0][d] + v * a[1][d] + w * a[2][d];
    if (normal) {
        double e1[3], e2[3];
        g1_sub(a[0], a[2], e1);
        g1_sub(a[1], a[2], e2);
        /* Each side scaled by a power of two near its largest component (exact, so the normal
         * is bit-identical where nothing overflows): the cross product of sides of 1e154 would
         * overflow (fuzz_smooth, a mesh at 2e148 whose tangents the micro-corner blending
         * lengthened) and of 1e-160 underflow to the zero vector. */
        g1_pow2_scale(e1);
        g1_pow2_scale(e2);
        g1_cross(e1, e2, normal);
        g1_normalize(normal);
    }
}


/* Step 2: the neighbour projected on the tangent plane at p (tan, g1_edge_tangents), a
 * fraction `tension` of the way. */
void g1_edge_point(const double *p, const double *tan, double tension, double *out)
{
    for (int k = 0; k < 3; k++)
        out[k] = p[k] + tension * tan[k];
}


/* The boundary curve as a degree-raised quadratic with middle point Q on the line where the
 * two vertex tangent planes meet, the point of that line closest to the quadratic that best
 * fits the thesis's cubic (Q* = (3 M1 - M0 + 3 M2 - M3) / 4). Used on the edges where eq. 9.4
 * is (nearly) dependent: there the thesis's cubic edge makes the system inconsistent (no G1
 * solution exists, e.g. on every edge of an octahedron), while a quadratic edge makes it
 * consistent (M1 - M0 + M3 - M2 = 2 (M2 - M1) is exactly the consistency condition). Returns 0
 * (and leaves out alone) when the planes are parallel or Q falls outside the edge's slab. */
static int quadratic_edge(const double *a, const double *na, const double *b, const double *nb,
                          const edge_ctrl *cubic, edge_ctrl *out)
{
    double qs[3], ab[3], u[3];
    for (int d = 0; d < 3; d++)
        qs[d] = (3 * cubic->p[0][d] - a[d] + 3 * cubic->p[1][d] - b[d]) / 4;
    g1_cross(na, nb, u);
    if (!(g1_dot(u, u) > 1e-12)) return 0;
    double m00 = g1_dot(na, na), m01 = g1_dot(na, nb), m11 = g1_dot(nb, nb), t0[3], t1[3];
    g1_sub(a, qs, t0);
    g1_sub(b, qs, t1);
    double r0 = g1_dot(na, t0), r1 = g1_dot(nb, t1), det = m00 * m11 - m01 * m01;
    double x = (r0 * m11 - r1 * m01) / det, y = (m00 * r1 - m01 * r0) / det, q[3];
    for (int d = 0; d < 3; d++)
        q[d] = qs[d] + x * na[d] + y * nb[d];
    g1_sub(b, a, ab);
    double len2 = g1_dot(ab, ab);
    g1_sub(q, a, t0);
    double along = g1_dot(t0, ab) / len2;
    if (!(along > 0.05 && along < 0.95) || g1_dot(t0, t0) > 4 * len2) return 0;
    /* The new tangent directions must stay close to the projected edges (within ~18
     * degrees), or the vertex stars that made the orientation condition hold could fold. */
    double o0[3], o1[3], q1[3];
    g1_sub(cubic->p[0], a, o0);
    g1_sub(cubic->p[1], b, o1);
    g1_sub(q, b, q1);
    if (!(g1_dot(t0, o0) > 0.95 * sqrt(g1_dot(t0, t0) * g1_dot(o0, o0))) ||
        !(g1_dot(q1, o1) > 0.95 * sqrt(g1_dot(q1, q1) * g1_dot(o1, o1))))
        return 0;
    for (int d = 0; d < 3; d++) {
        out->p[0][d] = (a[d] + 2 * q[d]) / 3;
        out->p[1][d] = (2 * q[d] + b[d]) / 3;
    }
    return 1;
}

/* Step 2 for every half-edge (quadratic where flagged), computed once an edge so the two
 * triangles share bit-identical boundary curves. */
static void boundary_curves(const fl_mesh *m, const double *normals, const double *tan,
                            double tension, const uint32_t *opp, const unsigned char *quad,
                            edge_ctrl *ep)
{
    for (size_t h = 0; h < 3 * m->triangle_count; h++) {
        if (opp[h] < h) continue;
        uint32_t a = m->tri[h], b = m->tri[3 * (h / 3) + (h + 1) % 3];
        const double *pa = m->xyz + 3 * a, *pb = m->xyz + 3 * b;
        edge_ctrl c;
        g1_edge_point(pa, tan + 3 * h, tension, c.p[0]);
        g1_edge_point(pb, tan + 3 * (size_t)opp[h], tension, c.p[1]);
        if (quad && quad[h]) quadratic_edge(pa, normals + 3 * a, pb, normals + 3 * b, &c, &c);
        ep[h] = c;
        memcpy(ep[opp[h]].p[0], c.p[1], sizeof c.p[1]);
        memcpy(ep[opp[h]].p[1], c.p[0], sizeof c.p[0]);
    }
}

/* Steps 1-4 for triangle t: the macro patch and the points of its three-split that depend only
 * on it (subdivision at P(1/3, 1/3, 1/3)). */
static void macro_patch(const fl_mesh *m, const edge_ctrl *ep, size_t t, macro_net *net)
{
    const uint32_t *v = m->tri + 3 * t;
    double sum_e[3] = {0, 0, 0}, sum_v[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
        uint32_t a = v[k];
        memcpy(net->e[k], ep[3 * t + (size_t)k].p, sizeof net->e[k]);
        for (int d = 0; d < 3; d++) {
            sum_e[d] += net->e[k][0][d] + net->e[k][1][d];
            sum_v[d] += m->xyz[3 * a + d];
        }
    }
    for (int d = 0; d < 3; d++)
        net->c111[d] = sum_e[d] / 4 - sum_v[d] / 6; /* step 3 */
    for (int k = 0; k < 3; k++) {
        const double *p = m->xyz + 3 * v[k];
        for (int d = 0; d < 3; d++) {
            /* blossom b(V_k, V_k, C) and b(V_k, V_k+1, C), C the centroid */
            net->w[k][d] = (p[d] + net->e[k][0][d] + net->e[(k + 2) % 3][1][d]) / 3;
            net->x[k][d] = (net->e[k][0][d] + net->e[k][1][d] + net->c111[d]) / 3;
        }
    }
}

/* The multipliers (e, f, g) with e d + f l + g r = 0 (eq. 9.3a / 9.3d): d, l, r lie in the
 * tangent plane with normal n, so the null vector is (l x r, r x d, d x l) . n. It is scaled
 * to f + g = -1, which gives the thesis's e = 1 whenever e can be 1, and still a solution
 * (e = 0) when l and r are parallel, i.e. both cross the edge at right angles. Returns 0 when
 * f + g = 0 (l and r on the same side: the orientation condition fails). */
int g1_edge_coefficients(const double *d, const double *l, const double *r, const double *n,
                             double *e, double *f, double *g)
{
    double c[3];
    g1_cross(l, r, c);
    *e = g1_dot(c, n);
    g1_cross(r, d, c);
    *f = g1_dot(c, n);
    g1_cross(d, l, c);
    *g = g1_dot(c, n);
    double s = -(*f + *g);
    if (s == 0 || !isfinite(s)) return 0;
    *e /= s;
    *f /= s;
    *g /= s;
    return 1;
}

typedef struct edge_frame {
    const double *m[4], *l0, *l2, *r0, *r2, *n0, *n3;
} edge_frame;

/* Step 5: L1 and R1 from eq. 9.4, with linear multipliers E, F, G.
 *
 * The end triples of eq. 9.3a and 9.3d are each fixed only up to a factor, and the solution
 * depends on the ratio of the two factors. The thesis sets e0 = e1 = 1; on an edge with a
 * mirror symmetry (every edge of an octahedron or a cube, many of a torus) eq. 9.4 is then
 * dependent AND inconsistent, and the surface breaks (we measured 16 degree normal jumps on the
 * octahedron). We normalise each end in its own frame instead: at M0 on the edge vector
 * M1 - M0 (eq. 9.3a as is); at M3 on M2 - M3 with the cross vectors L2 - M3, R2 - M3, which is
 * eq. 9.3d rewritten. The construction is then the same read from
 * either end of the edge, and a symmetric edge gives a dependent but consistent system.
 * The 2x2 matrix A = 2 [f0 g0; f1 g1] acts on each coordinate alike. When the equations are
 * independent the solution is unique; when they are dependent we take the solution with the
 * least displacement from the subdivision values: x = x_old + A^+ (B - A x_old), A^+ =
 * A^T / |A|_F^2 for rank one. Both are solved for the displacement from x_old with a
 * right-hand side built from differences, the independent case by g1_solve2_refined
 * (small_solve.c: Cramer's rule left 6.5e-7 degree jumps on nearly dependent edges). Returns
 * 1 for a dependent edge, -1 when an end has no solution. */
static int solve_edge(const edge_frame *q, double *l1, double *r1, double *conditioning)
{
    double d0[3], la[3], ra[3], d3[3], lb[3], rb[3], back[3], l3[3], r3[3];
    g1_sub(q->m[1], q->m[0], d0);
    g1_sub(q->l0, q->m[0], la);
    g1_sub(q->r0, q->m[0], ra);
    g1_sub(q->m[3], q->m[2], d3);
    g1_sub(q->l2, q->m[2], lb);
    g1_sub(q->r2, q->m[2], rb);
    g1_sub(q->m[2], q->m[3], back);
    g1_sub(q->l2, q->m[3], l3);
    g1_sub(q->r2, q->m[3], r3);
    double e0, f0, g0, e3, f1, g1;
    if (!g1_edge_coefficients(d0, la, ra, q->n0, &e0, &f0, &g0) ||
        !g1_edge_coefficients(back, l3, r3, q->n3, &e3, &f1, &g1))
        return -1;
    /* e3 (M2 - M3) + f1 (L2 - M3) + g1 (R2 - M3) = 0 is eq. 9.3d with e1 = -(e3 + f1 + g1). The
     * end-3 triple is then scaled to make (f1, g1) as close as possible to (f0, g0): on a
     * dependent edge this makes them equal, and with a quadratic boundary curve the system is
     * then consistent (see quadratic_edge). */
    double e1 = -(e3 + f1 + g1), rho = (f0 * f1 + g0 * g1) / (f1 * f1 + g1 * g1);
    if (rho > 0 && isfinite(rho)) {
        e1 *= rho;
        f1 *= rho;
        g1 *= rho;
    }
    double a00 = 2 * f0, a01 = 2 * g0, a10 = 2 * f1, a11 = 2 * g1;
    double det = a00 * a11 - a01 * a10;
    double fro = a00 * a00 + a01 * a01 + a10 * a10 + a11 * a11;
    int dependent = !(fabs(det) > 1e-12 * fro);
    *conditioning = fabs(det) / fro;
    const double a[2][2] = {{a00, a01}, {a10, a11}};
    for (int k = 0; k < 3; k++) {
        const double *M0 = q->m[0], *M1 = q->m[1], *M2 = q->m[2], *M3 = q->m[3];
        /* b - A x_old from differences only (no absolute coordinates): on a nearly dependent
         * edge the solution error is the residual times 1 / conditioning (up to 1e7 on
         * CGAL's torus_quad.off), so the residual must not carry eps |coordinates|. */
        long double s0 = -(long double)e1 * (M1[k] - M0[k]) - 2.0L * e0 * (M2[k] - M1[k]) -
                         (long double)f1 * la[k] - (long double)g1 * ra[k] -
                         (long double)a00 * (l1[k] - M1[k]) - (long double)a01 * (r1[k] - M1[k]);
        long double s1 = -2.0L * e1 * (M2[k] - M1[k]) - (long double)e0 * (M3[k] - M2[k]) -
                         (long double)f0 * lb[k] - (long double)g0 * rb[k] -
                         (long double)a10 * (l1[k] - M1[k]) - (long double)a11 * (r1[k] - M1[k]);
        double dl, dr;
        if (!dependent) {
            g1_solve2_refined(a, s0, s1, &dl, &dr);
        } else {
            dl = (double)((a00 * s0 + a10 * s1) / fro);
            dr = (double)((a01 * s0 + a11 * s1) / fro);
        }
        l1[k] += dl;
        r1[k] += dr;
    }
    return dependent;
}

static void put(double *ctrl, int i, int j, const double *p)
{
    memcpy(ctrl + 3 * net_index(3, i, j), p, 3 * sizeof(double));
}

/* Step 6 and the three micro patches (vertex k, vertex k+1, split point) of triangle t, written
 * as patches base, base + 1, base + 2. */
static void emit_three_split(const fl_mesh *m, size_t t, const macro_net *net, fl_g1_surface *s,
                             size_t base)
{
    const uint32_t *v = m->tri + 3 * t;
    double y[3][3], z[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++) {
            y[k][d] = (net->w[k][d] + net->x[k][d] + net->x[(k + 2) % 3][d]) / 3;
            z[d] += y[k][d] / 3;
        }
    for (int k = 0; k < 3; k++) {
        size_t p = base + (size_t)k;
        int k1 = (k + 1) % 3;
        double *c = s->ctrl + 30 * p;
        put(c, 3, 0, m->xyz + 3 * v[k]);
        put(c, 2, 1, net->e[k][0]);
        put(c, 1, 2, net->e[k][1]);
        put(c, 0, 3, m->xyz + 3 * v[k1]);
        put(c, 2, 0, net->w[k]);
        put(c, 1, 1, net->x[k]);
        put(c, 0, 2, net->w[k1]);
        put(c, 1, 0, y[k]);
        put(c, 0, 1, y[k1]);
        put(c, 0, 0, z);
        s->corner[3 * p] = v[k];
        s->corner[3 * p + 1] = v[k1];
        s->corner[3 * p + 2] = (uint32_t)(m->vertex_count + t);
        s->macro[p] = (uint32_t)t;
    }
}

void g1_macro_ctrl(const fl_mesh *m, size_t t, const macro_net *net, double ctrl[10][3])
{
    const uint32_t *v = m->tri + 3 * t;
    double *c = ctrl[0];
    put(c, 3, 0, m->xyz + 3 * v[0]);
    put(c, 0, 3, m->xyz + 3 * v[1]);
    put(c, 0, 0, m->xyz + 3 * v[2]);
    put(c, 2, 1, net->e[0][0]);
    put(c, 1, 2, net->e[0][1]);
    put(c, 0, 2, net->e[1][0]);
    put(c, 0, 1, net->e[1][1]);
    put(c, 1, 0, net->e[2][0]);
    put(c, 2, 0, net->e[2][1]);
    put(c, 1, 1, net->c111);
}

static void emit_macro(const fl_mesh *m, size_t t, const macro_net *net, fl_g1_surface *s)
{
    g1_macro_ctrl(m, t, net, (double(*)[3])(s->ctrl + 30 * t));
    memcpy(s->corner + 3 * t, m->tri + 3 * t, 3 * sizeof *m->tri);
    s->macro[t] = (uint32_t)t;
}

/* Step 5 on every macro edge, once an edge (from the half-edge with the smaller index). Flags
 * in quad the edges that are (nearly) dependent and still cubic; returns how many. */
/* |det A| / |A|_F^2 below which an edge gets a quadratic boundary curve. Measured: making every
 * feasible edge quadratic folds more patches on real meshes (elephant: 681 folded edges against
 * 135), so only the badly conditioned ones switch. */
static const double quadratic_below = 1e-3;

static size_t solve_macro_edges(const fl_mesh *m, const double *normals, macro_net *nets,
                                const uint32_t *opp, const uint32_t *pair_edge,
                                unsigned char *quad, fl_g1_surface *s, int *unsolvable)
{
    size_t flagged = 0;
    s->singular_edges = 0;
    for (size_t h = 0; h < 3 * m->triangle_count; h++) {
        if (opp[h] < h) continue;
        if (pair_edge && pair_edge[h / 3] == h) continue; /* inside a two-split pair */
        size_t t = h / 3, u = opp[h] / 3;
        int k = (int)(h % 3), j = (int)(opp[h] % 3), k1 = (k + 1) % 3, j1 = (j + 1) % 3;
        macro_net *P = nets + t, *Q = nets + u;
        uint32_t a = m->tri[h], b = m->tri[3 * t + (size_t)k1];
        edge_frame q = {{m->xyz + 3 * a, P->e[k][0], P->e[k][1], m->xyz + 3 * b},
                        P->w[k],
                        P->w[k1],
                        Q->w[j1],
                        Q->w[j],
                        normals + 3 * a,
                        normals + 3 * b};
        double cond = 0;
        int r = solve_edge(&q, P->x[k], Q->x[j], &cond);
        if (r < 0) *unsolvable = 1;
        s->singular_edges += r > 0;
        /* Below 1e-3 the cubic edge's solution is far from the subdivision values (the
         * oscillation of §9.6) or does not exist; a quadratic edge is consistent there. */
        if (cond < quadratic_below && !quad[h]) {
            quad[h] = 1;
            flagged++;
        }
    }
    return flagged;
}

/* Steps 1-5 of the three-split: rounds of boundary curves, macro patches and edge solves until
 * no further edge needs a quadratic boundary curve. */
static fl_status three_split_nets(const fl_mesh *m, const double *normals, const double *tan,
                                  double tension,
                                  const uint32_t *opp, const uint32_t *pair_edge, edge_ctrl *ep,
                                  macro_net *nets, fl_g1_surface *s, fl_error *err)
{
    unsigned char *quad = fl_calloc_array(3 * m->triangle_count, 1);
    if (!quad) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    int unsolvable = 0;
    for (int round = 0; round < 8; round++) {
        boundary_curves(m, normals, tan, tension, opp, quad, ep);
        for (size_t t = 0; t < m->triangle_count; t++)
            macro_patch(m, ep, t, nets + t);
        if (pair_edge) g1_pair_spoke_points(opp, pair_edge, m->triangle_count, nets);
        unsolvable = 0;
        if (!solve_macro_edges(m, normals, nets, opp, pair_edge, quad, s, &unsolvable)) break;
    }
    s->quadratic_edges = 0;
    for (size_t h = 0; h < 3 * m->triangle_count; h++)
        s->quadratic_edges += quad[h];
    free(quad);
    if (unsolvable)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "three-split: eq. 9.3a has no solution on some edge (its two triangles "
                       "project onto one line at a vertex)");
    return FL_OK;
}

static fl_status allocate(fl_g1_surface *s, size_t patches, size_t nv)
{
    s->patch_count = patches;
    s->vertex_count = nv;
    s->ctrl = fl_alloc_array(patches, 30 * sizeof(double));
    s->corner = fl_alloc_array(patches, 3 * sizeof(uint32_t));
    s->macro = fl_alloc_array(patches, sizeof(uint32_t));
    s->normal = fl_alloc_array(nv, 3 * sizeof(double));
    return s->ctrl && s->corner && s->macro && s->normal ? FL_OK : FL_ERR_NOMEM;
}

/* One scheme other than auto, before g1_snap_corner_points. */
static fl_status build_scheme(const fl_mesh *m, const fl_g1_surface_options *o, fl_g1_surface *s,
                              fl_error *err)
{
    size_t nt = m->triangle_count, nv = m->vertex_count;
    int two = o->scheme == FL_G1_TWO_SPLIT_AS_PRINTED, six = o->scheme == FL_G1_SIX_SPLIT;
    int cross = o->scheme == FL_G1_TWO_SPLIT;
    int split = o->scheme == FL_G1_THREE_SPLIT || two || cross;
    if (nt > (UINT32_MAX - nv) / 6) return fl_fail(err, FL_ERR_INPUT, NULL, -1, "mesh too big");
    if (allocate(s, six ? 6 * nt : split ? 3 * nt : nt, nv))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    s->node_count = split ? nv + nt : nv;
    fl_status st = fl_g1_vertex_normals(m, o->weighting, s->normal, err);
    if (!st)
        st =
            g1_repair_normals(m, s->normal, &s->orientation_repairs, &s->orientation_failures, err);
    if (st) return st;
    double tension = o->tension > 0 ? o->tension : 1.0 / 3.0;
    macro_net *nets = six ? NULL : fl_alloc_array(nt, sizeof *nets);
    edge_ctrl *ep = six ? NULL : fl_alloc_array(3 * nt, sizeof *ep);
    double *tan = fl_alloc_array(3 * nt, 3 * sizeof *tan);
    uint32_t *opp = NULL, *paired = two || cross ? fl_alloc_array(nt, sizeof *paired) : NULL;
    if ((!six && (!nets || !ep)) || !tan || ((two || cross) && !paired)) {
        free(nets);
        free(ep);
        free(tan);
        free(paired);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    st = g1_opposite_half_edges(m, &opp, err);
    size_t spread = 0;
    if (!st) st = g1_edge_tangents(m, s->normal, opp, o->scheme != FL_G1_MACRO, tan, &spread, err);
    if (!st && six) st = g1_six_split(m, s->normal, tan, tension, s, err);
    if (six) {
        free(tan);
        free(opp);
        return st;
    }
    if (!st && split) {
        if (cross) st = g1_choose_pairs(m, opp, paired, err);
        if (!st)
            st = three_split_nets(m, s->normal, tan, tension, opp, cross ? paired : NULL, ep,
                                  nets, s, err);
    } else if (!st) {
        boundary_curves(m, s->normal, tan, tension, opp, NULL, ep);
        for (size_t t = 0; t < nt; t++)
            macro_patch(m, ep, t, nets + t);
    }
    size_t np = 0; /* patches written: the two-split pairs first */
    if (!st && two) st = g1_two_split(m, s->normal, opp, nets, s, paired, &np, err);
    for (size_t t = 0; !st && cross && t < nt; t++) {
        if (paired[t] == UINT32_MAX || opp[paired[t]] < paired[t]) continue;
        np = g1_emit_cross_split(m, opp, paired[t], nets, s, np);
        s->two_split_pairs++;
    }
    for (size_t t = 0; !st && t < nt; t++) {
        if ((two || cross) && paired[t] != UINT32_MAX) continue;
        if (split) {
            emit_three_split(m, t, nets + t, s, np);
            np += 3;
        } else {
            emit_macro(m, t, nets + t, s);
            np++;
        }
    }
    if (!st) s->patch_count = np;
    free(nets);
    free(ep);
    free(tan);
    free(opp);
    free(paired);
    return st;
}

fl_status g1_build_checked(const fl_mesh *m, const fl_g1_surface_options *o, fl_g1_surface *s,
                          fl_error *err)
{
    if (o->scheme == FL_G1_AUTO) return g1_auto_build(m, o, s, err); /* snapped per component */
    fl_status st = build_scheme(m, o, s, err);
    /* PN triangles (FL_G1_MACRO) keep Vlachos et al.'s control points as computed (the test
     * compares them to 1e-14; the scheme is only C0, the baseline) */
    if (!st && o->scheme != FL_G1_MACRO) g1_snap_corner_points(s);
    return st;
}

fl_status fl_g1_surface_build(const fl_mesh *mesh, const fl_g1_surface_options *opt,
                              fl_g1_surface *out, fl_error *err)
{
    if (out) memset(out, 0, sizeof *out);
    if (!mesh || !out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL argument");
    fl_g1_surface_options o = opt ? *opt : (fl_g1_surface_options){0};
    if (o.scheme < 0 || o.scheme > FL_G1_AUTO || o.weighting < 0 ||
        o.weighting > FL_G1_WEIGHT_INVERSE || !(o.tension >= 0) || o.tension >= 1)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "bad surface options (scheme, weighting, tension in [0, 1))");
    fl_status st = g1_require_closed_mesh(mesh, err);
    if (!st) st = g1_build_checked(mesh, &o, out, err);
    if (st) fl_g1_surface_free(out);
    return st;
}

void fl_g1_surface_free(fl_g1_surface *surface)
{
    if (!surface) return;
    free(surface->ctrl);
    free(surface->corner);
    free(surface->macro);
    free(surface->normal);
    memset(surface, 0, sizeof *surface);
}

/* Independent checks for the smooth surfaces: patch edges paired by brute-force sorting,
 * normals compared at many points, and the Vlachos et al. (2001) PN-triangle control points
 * computed from their paper's formulas. */
#ifndef FL_TEST_G1_ORACLE_H
#define FL_TEST_G1_ORACLE_H

#include "g1_meshes.h"

typedef struct g1_pe {
    uint64_t key;
    uint32_t pe;
} g1_pe;

static int g1_pe_cmp(const void *a, const void *b)
{
    const g1_pe *x = a, *y = b;
    return x->key < y->key ? -1 : x->key > y->key ? 1 : (x->pe > y->pe) - (x->pe < y->pe);
}

/* The 3 * patch_count patch edges (edge k of patch p is p * 3 + k, from corner k to corner
 * k + 1) keyed by their unordered corner-node pair and sorted, so the two sides of an edge are
 * neighbours. malloc'd; free() it. */
static inline g1_pe *g1_sorted_patch_edges(const fl_g1_surface *s)
{
    size_t ne = 3 * s->patch_count;
    g1_pe *pe = malloc(ne * sizeof *pe);
    for (size_t i = 0; i < ne; i++) {
        uint64_t a = s->corner[i], b = s->corner[3 * (i / 3) + (i + 1) % 3];
        pe[i].key = a < b ? (a << 32 | b) : (b << 32 | a);
        pe[i].pe = (uint32_t)i;
    }
    qsort(pe, ne, sizeof *pe, g1_pe_cmp);
    return pe;
}

static inline double g1_angle_deg(const double *a, const double *b)
{
    double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    return atan2(sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                 a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) *
           57.295779513082320876798;
}

static inline void g1_edge_point(const fl_g1_surface *s, uint32_t pe, double t, double in,
                                 double *p, double *n)
{
    double bc[3];
    int e = (int)(pe % 3);
    bc[e] = (1 - t) * (1 - in);
    bc[(e + 1) % 3] = t * (1 - in);
    bc[(e + 2) % 3] = in;
    fl_g1_patch_eval(s->ctrl + 30 * (pe / 3), bc[0], bc[1], bc[2], p, n);
}

/* Over `samples`+1 points of every shared patch edge: the largest angle between the two
 * patches' normals, and the number of edges where the patches do not lie on opposite sides of
 * the edge (checked just inside each patch). *unpaired counts edges without a partner. */
static inline double g1_max_edge_jump(const fl_g1_surface *s, int samples, size_t *flips,
                                      size_t *unpaired)
{
    size_t ne = 3 * s->patch_count;
    g1_pe *pe = g1_sorted_patch_edges(s);
    double worst = 0;
    *flips = *unpaired = 0;
    for (size_t i = 0; i < ne; i++) {
        if (i + 1 == ne || pe[i].key != pe[i + 1].key) {
            (*unpaired)++;
            continue;
        }
        uint32_t a = pe[i].pe, b = pe[i + 1].pe;
        int flipped = 0;
        for (int k = 0; k <= samples; k++) {
            double t = (double)k / samples, pa[3], na[3], pb[3], nb[3], qa[3], qb[3];
            g1_edge_point(s, a, t, 0, pa, na);
            g1_edge_point(s, b, 1 - t, 0, pb, nb);
            double j = g1_angle_deg(na, nb);
            if (j > worst) worst = j;
            if (k == 0 || k == samples) continue;
            /* Opposite sides: the inward offsets of the two patches, projected across the
             * edge within the tangent plane, have opposite signs. */
            double ta[3], tb[3], c[3];
            g1_edge_point(s, a, t + 1e-6, 0, ta, NULL);
            g1_edge_point(s, a, t - 1e-6, 0, tb, NULL);
            for (int d = 0; d < 3; d++)
                ta[d] -= tb[d];
            c[0] = na[1] * ta[2] - na[2] * ta[1];
            c[1] = na[2] * ta[0] - na[0] * ta[2];
            c[2] = na[0] * ta[1] - na[1] * ta[0];
            g1_edge_point(s, a, t, 1e-5, qa, NULL);
            g1_edge_point(s, b, 1 - t, 1e-5, qb, NULL);
            double sa = 0, sb = 0;
            for (int d = 0; d < 3; d++) {
                sa += (qa[d] - pa[d]) * c[d];
                sb += (qb[d] - pa[d]) * c[d];
            }
            if (!(sa * sb < 0)) flipped = 1;
        }
        *flips += (size_t)flipped;
        i++;
    }
    free(pe);
    return worst;
}

/* Interpolation errors at the patch corners that are mesh vertices: verr = max coordinate
 * difference to the vertex, nerr = max coordinate difference of the patch normal to
 * s->normal, eerr (when est is not NULL) = max difference of s->normal to est. Returns how
 * many corners were checked. */
static inline size_t g1_corner_errors(const fl_g1_surface *s, const fl_mesh *m, const double *est,
                                      double *verr, double *nerr, double *eerr)
{
    size_t hits = 0;
    *verr = *nerr = 0;
    if (eerr) *eerr = 0;
    for (size_t p = 0; p < s->patch_count; p++)
        for (int c = 0; c < 3; c++) {
            uint32_t v = s->corner[3 * p + c];
            if (v >= m->vertex_count) continue;
            double pt[3], nn[3];
            fl_g1_patch_eval(s->ctrl + 30 * p, c == 0, c == 1, c == 2, pt, nn);
            for (int d = 0; d < 3; d++) {
                *verr = fmax(*verr, fabs(pt[d] - m->xyz[3 * v + d]));
                *nerr = fmax(*nerr, fabs(nn[d] - s->normal[3 * v + d]));
                if (est && eerr) *eerr = fmax(*eerr, fabs(s->normal[3 * v + d] - est[3 * v + d]));
            }
            hits++;
        }
    return hits;
}

/* Vlachos et al. 2001, "Curved PN triangles", geometry control points of triangle (p1, p2,
 * p3) with normals n1, n2, n3, in the order b300 b210 b201 b120 b111 b102 b030 b021 b012 b003. */
static inline void g1_pn_control_points(const double *p1, const double *p2, const double *p3,
                                        const double *n1, const double *n2, const double *n3,
                                        double *out)
{
    const double *P[3] = {p1, p2, p3}, *N[3] = {n1, n2, n3};
    double b[3][3][3]; /* b[i][j]: control point next to corner i on edge towards j */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            if (i == j) continue;
            double w = 0;
            for (int d = 0; d < 3; d++)
                w += (P[j][d] - P[i][d]) * N[i][d];
            for (int d = 0; d < 3; d++)
                b[i][j][d] = (2 * P[i][d] + P[j][d] - w * N[i][d]) / 3;
        }
    double E[3] = {0, 0, 0}, V[3];
    for (int d = 0; d < 3; d++) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                if (i != j) E[d] += b[i][j][d] / 6;
        V[d] = (p1[d] + p2[d] + p3[d]) / 3;
    }
    const double *order[10] = {p1,      b[0][1], b[0][2], b[1][0], NULL,
                               b[2][0], p2,      b[1][2], b[2][1], p3};
    for (int k = 0; k < 10; k++)
        for (int d = 0; d < 3; d++)
            out[3 * k + d] = order[k] ? order[k][d] : E[d] + (E[d] - V[d]) / 2;
}

#endif /* FL_TEST_G1_ORACLE_H */

/* The two-split of thesis §9.7 ("Towards an adaptive splitting scheme"), used inside a
 * three-split surface exactly as the thesis describes it.
 *
 * Which triangles. §9.7 opens with "very thin triangles can emerge [from the three-split]. This
 * may cause numerically instable computations": a triangle is *thin* here when its three-split
 * (at the centroid) would make a micro triangle with an angle below THIN_DEG, and it is split in
 * two instead when splitting it and its neighbour across one edge at that edge's midpoint gives
 * micro triangles whose smallest angle is larger than both three-splits'. §9.7 needs "the two
 * two-split triangles [to] have four three-split triangles as neighbors", so pairs are chosen
 * greedily, thinnest first, and the neighbours of a chosen pair are never paired themselves.
 *
 * Naming (Figure 9.6, reconstructed): P = (A, B, C) and Q = (B, A, D) share the edge A -> B and
 * are split at S = P(1/2, 1/2, 0) = Q(1/2, 1/2, 0). Around S counter-clockwise the four spokes go
 * to V_0..V_3 = B, C, A, D; micro triangle i is (V_i, V_i+1, S) and its outer edge V_i -> V_i+1
 * is a macro edge of P (i = 0, 1) or Q (i = 2, 3). On spoke i the control points are V_i, W_i,
 * Y_i, Z; X_i is the inner point of micro triangle i next to its outer edge.
 *
 * Step 4: every control point of the four micro triangles by subdivision (blossoming) of the
 * macro patches. Step 5: constant multipliers along each spoke (eq. 9.5), fixed at V_i by the
 * tangent plane there (eq. 9.5a), give eq. 9.6: 8 vector equations in X_i, Y_i, Z (9 points);
 * we take the solution of least squared displacement from the step-4 values (the thesis's
 * objective with squared norms, which makes it a linear least-norm problem).
 * Step 6 (neighbours): on an outer edge X_i is now fixed and the three-split neighbour's inner
 * point R1 is set from eq. 9.7 with constant multipliers: (e, f, g) from eq. 9.7a at M0, then
 * R1 from eq. 9.7b - 9.7a. docs/smooth.md measures what this leaves at the M3 end (eq. 9.7e). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smooth/smooth_internal.h"

/* A three-split micro angle below this (degrees) makes a triangle thin. */
static const double THIN_DEG = 15.0;

static double angle_at(const double *a, const double *b, const double *c)
{
    double u[3], v[3], x[3];
    g1_sub(b, a, u);
    g1_sub(c, a, v);
    g1_cross(u, v, x);
    return atan2(g1_length(x), g1_dot(u, v)) * (180.0 / 3.14159265358979323846);
}

static double min_angle(const double *a, const double *b, const double *c)
{
    return fmin(angle_at(a, b, c), fmin(angle_at(b, c, a), angle_at(c, a, b)));
}

/* Smallest angle of the three-split of triangle t (flat, at the centroid). NaN stays NaN. */
static double three_split_angle(const fl_mesh *m, size_t t)
{
    const double *p[3];
    double c[3];
    for (int k = 0; k < 3; k++)
        p[k] = m->xyz + 3 * m->tri[3 * t + (size_t)k];
    for (int d = 0; d < 3; d++)
        c[d] = (p[0][d] + p[1][d] + p[2][d]) / 3;
    double r = INFINITY;
    for (int k = 0; k < 3; k++) {
        double a = min_angle(p[k], p[(k + 1) % 3], c);
        r = isnan(a) ? a : fmin(r, a);
    }
    return r;
}

/* Smallest angle of the two-split of triangle t at the midpoint of its edge k. */
static double two_split_angle(const fl_mesh *m, size_t t, int k)
{
    const double *a = m->xyz + 3 * m->tri[3 * t + (size_t)k];
    const double *b = m->xyz + 3 * m->tri[3 * t + (size_t)(k + 1) % 3];
    const double *c = m->xyz + 3 * m->tri[3 * t + (size_t)(k + 2) % 3];
    double s[3];
    for (int d = 0; d < 3; d++)
        s[d] = (a[d] + b[d]) / 2;
    return fmin(min_angle(a, s, c), min_angle(s, b, c));
}

typedef struct candidate {
    double angle;
    uint32_t h; /* the half-edge to split across */
} candidate;

static int by_angle(const void *x, const void *y)
{
    const candidate *a = x, *b = y;
    return (a->angle > b->angle) - (a->angle < b->angle);
}

/* The four outer half-edges of the pair split across half-edge h (micro triangles 0..3). */
static void outer_half_edges(const uint32_t *opp, uint32_t h, uint32_t out[4])
{
    uint32_t q = opp[h], P = h / 3, Q = q / 3, k = h % 3, j = q % 3;
    out[0] = 3 * P + (k + 1) % 3;
    out[1] = 3 * P + (k + 2) % 3;
    out[2] = 3 * Q + (j + 1) % 3;
    out[3] = 3 * Q + (j + 2) % 3;
}

/* Greedy pairing (thinnest first); pair_edge[t] = the half-edge of t split, or UINT32_MAX. */
fl_status g1_choose_pairs(const fl_mesh *m, const uint32_t *opp, uint32_t *pair_edge,
                          fl_error *err)
{
    size_t nt = m->triangle_count, nc = 0;
    candidate *c = fl_alloc_array(nt, sizeof *c);
    unsigned char *state = fl_calloc_array(nt, 1); /* 1 paired, 2 next to a pair */
    if (!c || !state) {
        free(c);
        free(state);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    for (size_t t = 0; t < nt; t++) {
        pair_edge[t] = UINT32_MAX;
        double a3 = three_split_angle(m, t);
        if (!(a3 < THIN_DEG)) continue; /* also skips NaN */
        int best = -1;
        double best_angle = 0;
        for (int k = 0; k < 3; k++) {
            uint32_t h = (uint32_t)(3 * t + (size_t)k), q = opp[h];
            double a2 = fmin(two_split_angle(m, t, k), two_split_angle(m, q / 3, (int)(q % 3)));
            double floor3 = fmin(a3, three_split_angle(m, q / 3));
            if (a2 > floor3 && a2 > best_angle) {
                best = k;
                best_angle = a2;
            }
        }
        if (best >= 0) c[nc++] = (candidate){a3, (uint32_t)(3 * t + (size_t)best)};
    }
    qsort(c, nc, sizeof *c, by_angle);
    for (size_t i = 0; i < nc; i++) {
        uint32_t h = c[i].h, P = h / 3, Q = opp[h] / 3, out[4];
        if (P == Q || state[P] || state[Q]) continue;
        outer_half_edges(opp, h, out);
        int ok = 1;
        for (int k = 0; k < 4; k++) {
            uint32_t n = opp[out[k]] / 3;
            if (n == P || n == Q || state[n] == 1) ok = 0;
        }
        if (!ok) continue;
        state[P] = state[Q] = 1;
        for (int k = 0; k < 4; k++)
            state[opp[out[k]] / 3] = 2;
        pair_edge[P] = h;
        pair_edge[Q] = opp[h];
    }
    free(c);
    free(state);
    return FL_OK;
}

/* x = x_old + A^T y with (A A^T) y = b - A x_old: the solution of A x = b closest to x_old
 * (rows x 9 unknowns, each of the 3 coordinates alike). Gauss-Jordan with full pivoting; a
 * pivot below 1e-13 of the largest is taken as a dependent row (A^T y is the same for every y
 * solving a consistent singular system). Returns the number of dependent rows. */
enum { ROWS = 8, UNK = 9 };

static int least_displacement(const double A[ROWS][UNK], const double b[ROWS][3],
                              double x[UNK][3])
{
    double N[ROWS][ROWS + 3];
    for (int i = 0; i < ROWS; i++) {
        for (int j = 0; j < ROWS; j++) {
            N[i][j] = 0;
            for (int k = 0; k < UNK; k++)
                N[i][j] += A[i][k] * A[j][k];
        }
        for (int d = 0; d < 3; d++) {
            N[i][ROWS + d] = b[i][d];
            for (int k = 0; k < UNK; k++)
                N[i][ROWS + d] -= A[i][k] * x[k][d];
        }
    }
    int perm[ROWS], used[ROWS] = {0}, dependent = 0;
    double big = 0;
    for (int i = 0; i < ROWS; i++)
        big = fmax(big, fabs(N[i][i]));
    double y[ROWS][3] = {{0}};
    for (int step = 0; step < ROWS; step++) {
        int pr = -1, pc = -1;
        double best = 0;
        for (int i = 0; i < ROWS; i++)
            for (int j = 0; j < ROWS; j++)
                if (!used[j] && fabs(N[i][j]) > best && (i >= step)) {
                    best = fabs(N[i][j]);
                    pr = i;
                    pc = j;
                }
        if (pr < 0 || !(best > 1e-13 * big)) {
            dependent = ROWS - step;
            break;
        }
        for (int j = 0; j < ROWS + 3; j++) {
            double t = N[pr][j];
            N[pr][j] = N[step][j];
            N[step][j] = t;
        }
        used[pc] = 1;
        perm[step] = pc;
        for (int i = 0; i < ROWS; i++) {
            if (i == step || N[i][pc] == 0) continue;
            double f = N[i][pc] / N[step][pc];
            for (int j = 0; j < ROWS + 3; j++)
                N[i][j] -= f * N[step][j];
        }
    }
    for (int step = 0; step < ROWS - dependent; step++)
        for (int d = 0; d < 3; d++)
            y[perm[step]][d] = N[step][ROWS + d] / N[step][perm[step]];
    for (int k = 0; k < UNK; k++)
        for (int d = 0; d < 3; d++)
            for (int i = 0; i < ROWS; i++)
                x[k][d] += A[i][k] * y[i][d];
    return dependent;
}

/* One pair: the four micro nets (ctrl[i], corners V_i, V_i+1, S) after steps 4 and 5. Returns
 * 0 when a spoke has no multipliers (eq. 9.5a degenerate) or a value is not finite. */
typedef struct pair_net {
    uint32_t v[4];     /* B, C, A, D */
    uint32_t tri[4];   /* macro triangle of micro triangle i */
    uint32_t outer[4]; /* half-edge V_i -> V_i+1 */
    double ctrl[4][10][3];
    int dependent;
} pair_net;

static int build_pair(const fl_mesh *m, const double *normals, const uint32_t *opp,
                      const macro_net *nets, uint32_t h, pair_net *pn)
{
    uint32_t q = opp[h], P = h / 3, Q = q / 3;
    int k = (int)(h % 3), j = (int)(q % 3);
    double netP[10][3], netQ[10][3];
    g1_macro_ctrl(m, P, nets + P, netP);
    g1_macro_ctrl(m, Q, nets + Q, netQ);
    double unit[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, sP[3] = {0}, sQ[3] = {0};
    sP[k] = sP[(k + 1) % 3] = 0.5;
    sQ[j] = sQ[(j + 1) % 3] = 0.5;
    /* corner of V_i in the owner of micro triangle i and of V_i+1 */
    const double *bary[4][2] = {{unit[(k + 1) % 3], unit[(k + 2) % 3]},
                                {unit[(k + 2) % 3], unit[k]},
                                {unit[(j + 1) % 3], unit[(j + 2) % 3]},
                                {unit[(j + 2) % 3], unit[j]}};
    pn->v[0] = m->tri[3 * P + (size_t)(k + 1) % 3];
    pn->v[1] = m->tri[3 * P + (size_t)(k + 2) % 3];
    pn->v[2] = m->tri[h];
    pn->v[3] = m->tri[3 * Q + (size_t)(j + 2) % 3];
    outer_half_edges(opp, h, pn->outer);
    for (int i = 0; i < 4; i++) {
        pn->tri[i] = i < 2 ? P : Q;
        const double(*net)[3] = i < 2 ? netP : netQ, *s = i < 2 ? sP : sQ;
        for (int a = 0; a <= 3; a++)
            for (int b = 0; a + b <= 3; b++) {
                const double *arg[3];
                int n = 0;
                for (int r = 0; r < a; r++)
                    arg[n++] = bary[i][0];
                for (int r = 0; r < b; r++)
                    arg[n++] = bary[i][1];
                while (n < 3)
                    arg[n++] = s;
                g1_blossom(net, arg[0], arg[1], arg[2], pn->ctrl[i][g1_ix(a, b)]);
            }
        /* corners and outer edge bit-identical with the neighbours' */
        uint32_t o = pn->outer[i];
        const macro_net *T = nets + o / 3;
        memcpy(pn->ctrl[i][g1_ix(3, 0)], m->xyz + 3 * pn->v[i], sizeof(double[3]));
        memcpy(pn->ctrl[i][g1_ix(0, 3)], m->xyz + 3 * pn->v[(i + 1) % 4], sizeof(double[3]));
        memcpy(pn->ctrl[i][g1_ix(2, 1)], T->e[o % 3][0], sizeof(double[3]));
        memcpy(pn->ctrl[i][g1_ix(1, 2)], T->e[o % 3][1], sizeof(double[3]));
    }
    /* the shared spokes A-S and B-S and Z: one value (P's) for both sides */
    double W[4][3], X[UNK][3];
    for (int i = 0; i < 4; i++) {
        memcpy(W[i], pn->ctrl[i][g1_ix(2, 0)], sizeof W[i]);
        memcpy(X[i], pn->ctrl[i][g1_ix(1, 1)], sizeof X[i]);
        memcpy(X[4 + i], pn->ctrl[i][g1_ix(1, 0)], sizeof X[i]);
    }
    memcpy(X[8], pn->ctrl[0][g1_ix(0, 0)], sizeof X[8]);
    memcpy(W[2], pn->ctrl[1][g1_ix(0, 2)], sizeof W[2]);
    memcpy(X[6], pn->ctrl[1][g1_ix(0, 1)], sizeof X[6]);
    /* Step 5: eq. 9.6a, 9.6b for spoke i between micro triangles i-1 (f) and i (g). */
    double A[ROWS][UNK] = {{0}}, rhs[ROWS][3] = {{0}};
    for (int i = 0; i < 4; i++) {
        int il = (i + 3) % 4;
        const double *V = m->xyz + 3 * pn->v[i];
        double d[3], l[3], r[3], e, f, g;
        g1_sub(W[i], V, d);
        g1_sub(pn->ctrl[il][g1_ix(1, 2)], V, l);
        g1_sub(pn->ctrl[i][g1_ix(2, 1)], V, r);
        if (!g1_edge_coefficients(d, l, r, normals + 3 * pn->v[i], &e, &f, &g)) return 0;
        A[2 * i][4 + i] = e; /* e (Y_i - W_i) + f (X_i-1 - W_i) + g (X_i - W_i) = 0 */
        A[2 * i][il] = f;
        A[2 * i][i] = g;
        for (int c = 0; c < 3; c++)
            rhs[2 * i][c] = (e + f + g) * W[i][c];
        A[2 * i + 1][8] = e; /* e (Z - Y_i) + f (Y_i-1 - Y_i) + g (Y_i+1 - Y_i) = 0 */
        A[2 * i + 1][4 + il] = f;
        A[2 * i + 1][4 + (i + 1) % 4] = g;
        A[2 * i + 1][4 + i] = -(e + f + g);
    }
    pn->dependent = least_displacement(A, rhs, X);
    least_displacement(A, rhs, X); /* one refinement step against rounding */
    for (int i = 0; i < 4; i++) {
        int i1 = (i + 1) % 4;
        double(*c)[3] = pn->ctrl[i];
        memcpy(c[g1_ix(2, 0)], W[i], sizeof W[i]);
        memcpy(c[g1_ix(0, 2)], W[i1], sizeof W[i]);
        memcpy(c[g1_ix(1, 1)], X[i], sizeof X[i]);
        memcpy(c[g1_ix(1, 0)], X[4 + i], sizeof X[i]);
        memcpy(c[g1_ix(0, 1)], X[4 + i1], sizeof X[i]);
        memcpy(c[g1_ix(0, 0)], X[8], sizeof X[8]);
    }
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 10; c++)
            for (int d = 0; d < 3; d++)
                if (!isfinite(pn->ctrl[i][c][d])) return 0;
    return 1;
}

/* Eq. 9.7 on outer edge i of a pair: constant (e, f, g) from eq. 9.7a at M0 = V_i, then the
 * neighbour's inner point R1 from 2e (M2 - M1) + 2f (L1 - M1) + 2g (R1 - M1) = 0. */
static void solve_outer_edge(const double *normals, const uint32_t *opp,
                             const pair_net *pn, int i, macro_net *nets)
{
    uint32_t o = pn->outer[i], hn = opp[o];
    macro_net *N = nets + hn / 3;
    int jj = (int)(hn % 3);
    const double(*c)[3] = pn->ctrl[i];
    const double *M0 = c[g1_ix(3, 0)], *M1 = c[g1_ix(2, 1)], *M2 = c[g1_ix(1, 2)];
    const double *L0 = c[g1_ix(2, 0)], *L1 = c[g1_ix(1, 1)], *R0 = N->w[(jj + 1) % 3];
    double d[3], l[3], r[3], e, f, g;
    g1_sub(M1, M0, d);
    g1_sub(L0, M0, l);
    g1_sub(R0, M0, r);
    if (!g1_edge_coefficients(d, l, r, normals + 3 * pn->v[i], &e, &f, &g) || g == 0) return;
    for (int k = 0; k < 3; k++)
        N->x[jj][k] = M1[k] - (e * (M2[k] - M1[k]) + f * (L1[k] - M1[k])) / g;
}

fl_status g1_two_split(const fl_mesh *m, const double *normals, const uint32_t *opp,
                       macro_net *nets, fl_g1_surface *s, uint32_t *paired, size_t *patches,
                       fl_error *err)
{
    size_t nt = m->triangle_count;
    *patches = 0;
    s->two_split_pairs = 0;
    fl_status st = g1_choose_pairs(m, opp, paired, err);
    if (st) return st;
    for (size_t t = 0; t < nt; t++) {
        uint32_t h = paired[t];
        if (h == UINT32_MAX || opp[h] < h) continue;
        pair_net pn;
        if (!build_pair(m, normals, opp, nets, h, &pn)) {
            paired[t] = paired[opp[h] / 3] = UINT32_MAX; /* stays three-split */
            continue;
        }
        for (int i = 0; i < 4; i++)
            solve_outer_edge(normals, opp, &pn, i, nets);
        uint32_t node = (uint32_t)(m->vertex_count + (t < opp[h] / 3 ? t : opp[h] / 3));
        for (int i = 0; i < 4; i++) {
            size_t p = (*patches)++;
            memcpy(s->ctrl + 30 * p, pn.ctrl[i], sizeof pn.ctrl[i]);
            s->corner[3 * p] = pn.v[i];
            s->corner[3 * p + 1] = pn.v[(i + 1) % 4];
            s->corner[3 * p + 2] = node;
            s->macro[p] = pn.tri[i];
        }
        s->singular_edges += pn.dependent > 0;
        s->two_split_pairs++;
    }
    /* paired[] now holds the partner triangle for the caller */
    for (size_t t = 0; t < nt; t++)
        if (paired[t] != UINT32_MAX) paired[t] = opp[paired[t]] / 3;
    return FL_OK;
}

/* ---- The G1 variant: each pair as one C1 cross split (docs/smooth.md) ----
 *
 * The pair's quad B, C, A, D is taken over the square domain b = (1, 0), c = (0, 1),
 * a = (-1, 0), d = (0, -1) with S at the origin, where its diagonals cross (the Fraeijs de
 * Veubeke-Sander / Sibson split). On every spoke the domain gives s - v_i = (v_i-1 - v_i)/2 +
 * (v_i+1 - v_i)/2, so the four micro patches are C1 over the square exactly when, row by row,
 *   W_i = (E_i-1,1 + E_i,0) / 2,   Y_i = (X_i-1 + X_i) / 2,   Z = (Y_i-1 + Y_i+1) / 2,
 * and the last is consistent for every i: Z = (X_0 + X_1 + X_2 + X_3) / 4. The four X_i stay
 * free; they are the pair's inner points on its four outer edges and are solved there by
 * eq. 9.4 together with the three-split neighbours' R1, exactly as on a three-split edge. The
 * Y_i - Z lie on the two domain diagonals' images, so the corner at S is regular. */

void g1_pair_spoke_points(const uint32_t *opp, const uint32_t *pair_edge, size_t nt,
                          macro_net *nets)
{
    for (size_t t = 0; t < nt; t++) {
        uint32_t h = pair_edge[t];
        if (h == UINT32_MAX || opp[h] < h) continue;
        uint32_t q = opp[h];
        int k = (int)(h % 3), j = (int)(q % 3), k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        macro_net *P = nets + t, *Q = nets + q / 3;
        for (int d = 0; d < 3; d++) {
            double wb = (P->e[k1][0][d] + Q->e[j2][1][d]) / 2; /* B: edges B->C, D->B */
            double wc = (P->e[k2][0][d] + P->e[k1][1][d]) / 2; /* C: edges C->A, B->C */
            double wa = (P->e[k2][1][d] + Q->e[j1][0][d]) / 2; /* A: edges C->A, A->D */
            double wd = (Q->e[j2][0][d] + Q->e[j1][1][d]) / 2; /* D: edges D->B, A->D */
            P->w[k1][d] = Q->w[j][d] = wb;
            P->w[k][d] = Q->w[j1][d] = wa;
            P->w[k2][d] = wc;
            Q->w[j2][d] = wd;
        }
    }
}

size_t g1_emit_cross_split(const fl_mesh *m, const uint32_t *opp, uint32_t h,
                           const macro_net *nets, fl_g1_surface *s, size_t p)
{
    uint32_t q = opp[h], P = h / 3, Q = q / 3;
    int k = (int)(h % 3), j = (int)(q % 3);
    const macro_net *nP = nets + P, *nQ = nets + Q;
    const uint32_t v[4] = {m->tri[3 * P + (size_t)(k + 1) % 3], m->tri[3 * P + (size_t)(k + 2) % 3],
                           m->tri[h], m->tri[3 * Q + (size_t)(j + 2) % 3]};
    const macro_net *own[4] = {nP, nP, nQ, nQ};
    const int edge[4] = {(k + 1) % 3, (k + 2) % 3, (j + 1) % 3, (j + 2) % 3};
    double y[4][3], z[3] = {0, 0, 0};
    for (int i = 0; i < 4; i++)
        for (int d = 0; d < 3; d++) {
            const double *x0 = own[(i + 3) % 4]->x[edge[(i + 3) % 4]], *x1 = own[i]->x[edge[i]];
            y[i][d] = (x0[d] + x1[d]) / 2;
            z[d] += x1[d] / 4;
        }
    uint32_t node = (uint32_t)(m->vertex_count + (P < Q ? P : Q));
    for (int i = 0; i < 4; i++, p++) {
        int i1 = (i + 1) % 4;
        double(*c)[3] = (double(*)[3])(s->ctrl + 30 * p);
        const macro_net *o = own[i], *o1 = own[i1];
        memcpy(c[g1_ix(3, 0)], m->xyz + 3 * v[i], sizeof c[0]);
        memcpy(c[g1_ix(0, 3)], m->xyz + 3 * v[i1], sizeof c[0]);
        memcpy(c[g1_ix(2, 1)], o->e[edge[i]][0], sizeof c[0]);
        memcpy(c[g1_ix(1, 2)], o->e[edge[i]][1], sizeof c[0]);
        memcpy(c[g1_ix(2, 0)], o->w[edge[i]], sizeof c[0]);            /* W at V_i */
        memcpy(c[g1_ix(0, 2)], o1->w[edge[i1]], sizeof c[0]);          /* W at V_i+1 */
        memcpy(c[g1_ix(1, 1)], o->x[edge[i]], sizeof c[0]);
        memcpy(c[g1_ix(1, 0)], y[i], sizeof c[0]);
        memcpy(c[g1_ix(0, 1)], y[i1], sizeof c[0]);
        memcpy(c[g1_ix(0, 0)], z, sizeof c[0]);
        s->corner[3 * p] = v[i];
        s->corner[3 * p + 1] = v[i1];
        s->corner[3 * p + 2] = node;
        s->macro[p] = i < 2 ? P : Q;
    }
    return p;
}

/* The cubic six-split of thesis §9.8, in a form that is consistent (docs/smooth.md explains
 * why the equations as printed have no regular solution and what changed).
 *
 * Every macro triangle (V0, V1, V2) is split at its edge midpoints m_i = P(1/2, 1/2, 0) ... and
 * its centre O = P(1/3, 1/3, 1/3) into six micro triangles: 2i = (V_i, m_i, O) and
 * 2i + 1 = (m_i, V_i+1, O), m_i the midpoint of edge i (V_i -> V_i+1). Names follow Figure 9.7
 * where it can be reconstructed: on the spoke from V_i to O the control points are
 * V_i, N_i, Q_i, O; on the spoke from m_i to O they are m_i, Nm_i, Qm_i, O; the centre control
 * point of micro triangle p is P_p; along a macro edge the half-edge from vertex A to m has
 * A, K_A, Y_A, m.
 *
 * Step 0: the multipliers are constant along every spoke (eq. 9.8), a = 1, b = c on the vertex
 * spokes and h, k = l on the midpoint spokes with k = -(2b + 1)/(3b + 2). The only b for which
 * the midpoint spokes are consistent at m (where Y_A - m = -(Y_B - m), so eq. 9.8a reads
 * h (Nm - m) = 0) is b = -2/3, h = 0: then the six patches are C1 over the macro domain, and
 * steps 4, 6 and 7 are the C1 conditions:
 *   N_i = (2/3)(K + K') - V_i / 3              (eq. 9.14, K, K' on the two edges at V_i)
 *   Q_i = (2/3)(P_2i + P_2i-1) - N_i / 3       (eq. 9.13a)
 *   Nm_i = (P_2i + P_2i+1) / 2, Qm_i = (Q_i + Q_i+1) / 2   (eq. 9.12a, 9.12b with h = 0)
 *   O = (Q_0 + Q_1 + Q_2) / 3                  (step 6; the thesis's "O = (Q1 + Q3 + Q5)/3")
 * Step 5 (the minimal-displacement solve) then makes each macro edge G1: the two half-edges
 * get linear multipliers (eq. 9.3 on each half, the end at V fixed by the vertex tangent plane,
 * the end at m by the tangent plane there) and the free points around m -- m itself, Y_A, and
 * the four centres P next to the edge -- move as little as possible from their subdivision
 * values under the five independent vector equations. The coefficient of Y - m in the triple
 * at m is free; where its subdivision value leaves the system inconsistent (a mirror plane
 * through the edge) or collapses the midpoint spokes onto m (a mirror plane across it), it is
 * searched per edge (midpoint_multiplier_search, midpoint_spoke_search; docs/smooth.md). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smooth/smooth_internal.h"

static int ix(int i, int j)
{
    return (3 - i) * (4 - i) / 2 + (3 - i - j);
}

/* The blossom (polar form) of the cubic with control points net at barycentric u1, u2, u3:
 * the control points of any sub-triangle are blossom values of its corners (§9.5, Goldman). */
void g1_blossom(const double net[10][3], const double *u1, const double *u2, const double *u3,
                    double *out)
{
    const double *arg[3] = {u1, u2, u3};
    double a[10][3], b[10][3];
    memcpy(a, net, sizeof a);
    for (int n = 3; n > 0; n--) {
        const double *w = arg[3 - n];
        for (int i = 0; i < n; i++)
            for (int j = 0; i + j < n; j++) {
                int to = (n - 1 - i) * (n - i) / 2 + (n - 1 - i - j);
                int f0 = (n - i - 1) * (n - i) / 2 + (n - i - 1 - j);  /* (i + 1, j) */
                int f1 = (n - i) * (n - i + 1) / 2 + (n - i - j - 1);  /* (i, j + 1) */
                int f2 = (n - i) * (n - i + 1) / 2 + (n - i - j);      /* (i, j) */
                for (int d = 0; d < 3; d++)
                    b[to][d] = w[0] * a[f0][d] + w[1] * a[f1][d] + w[2] * a[f2][d];
            }
        memcpy(a, b, sizeof a);
    }
    memcpy(out, a[0], 3 * sizeof(double));
}

/* Per macro triangle: the macro patch (steps 1-3), the vertex-spoke points N and the six
 * micro centres P (subdivision values, then step 5). */
typedef struct six_tri {
    double net[10][3];
    double n[3][3];
    double p[6][3];
} six_tri;

/* Per half-edge h: the split point m and the points next to it on the half from h's start
 * (ya) and from its end (yb), and the split ratio lam: the domain position of m on the edge,
 * measured from h's start (1/2 unless step 5 needed another); the two half-edges of an edge
 * hold the same values, swapped, and lam and 1 - lam. */
typedef struct six_edge {
    double m[3], ya[3], yb[3], lam;
} six_edge;

/* A point as a known vector plus a combination of the six unknowns of an edge solve. */
typedef struct lin {
    double c[6], k[3];
} lin;

static lin known(const double *p)
{
    lin r = {{0}, {p[0], p[1], p[2]}};
    return r;
}

static lin var2(int i, double a, int j, double b)
{
    lin r = {{0}, {0, 0, 0}};
    r.c[i] += a;
    r.c[j] += b;
    return r;
}

/* Row += coef * (p - q). */
static void acc(double *row, double *rhs, double coef, const lin *p, const lin *q)
{
    for (int i = 0; i < 6; i++)
        row[i] += coef * (p->c[i] - q->c[i]);
    for (int d = 0; d < 3; d++)
        rhs[d] -= coef * (p->k[d] - q->k[d]);
}

/* The four equations of eq. 9.3 on one half-edge, written as rows over the unknowns:
 * m[0..3] the boundary points (M0 at the vertex), l[0..2], r[0..2] the cross rows of the two
 * sides; (e0, f0, g0) at M0, (e1, f1, g1) at M3. C0 holds by the choice of the end triple at
 * M0 and C3 is added once an edge by the caller, so this adds C1 and C2. */
static void half_edge_rows(const lin *m, const lin *l, const lin *r, const double *c0,
                           const double *c1, double rows[][6], double rhs[][3])
{
    double e0 = c0[0], f0 = c0[1], g0 = c0[2], e1 = c1[0], f1 = c1[1], g1 = c1[2];
    acc(rows[0], rhs[0], e1, &m[1], &m[0]);
    acc(rows[0], rhs[0], 2 * e0, &m[2], &m[1]);
    acc(rows[0], rhs[0], f1, &l[0], &m[0]);
    acc(rows[0], rhs[0], 2 * f0, &l[1], &m[1]);
    acc(rows[0], rhs[0], g1, &r[0], &m[0]);
    acc(rows[0], rhs[0], 2 * g0, &r[1], &m[1]);
    acc(rows[1], rhs[1], 2 * e1, &m[2], &m[1]);
    acc(rows[1], rhs[1], e0, &m[3], &m[2]);
    acc(rows[1], rhs[1], 2 * f1, &l[1], &m[1]);
    acc(rows[1], rhs[1], f0, &l[2], &m[2]);
    acc(rows[1], rhs[1], 2 * g1, &r[1], &m[1]);
    acc(rows[1], rhs[1], g0, &r[2], &m[2]);
}

/* Solves G z = r for the 5 x 5 Gram matrix G = A A^T (symmetric positive semidefinite) by
 * symmetric elimination with the largest remaining diagonal as pivot; pivots below tol end
 * it (rank deficient: those z are 0). Any solution z gives the same A^T z when the system is
 * consistent, so x = x_old + A^T z is still the least displacement. Returns the rank. */
static int solve_gram(double g[5][5], double r[5][3], double tol, double z[5][3])
{
    int perm[5] = {0, 1, 2, 3, 4}, rank = 5;
    for (int c = 0; c < 5; c++) {
        int p = c;
        for (int i = c + 1; i < 5; i++)
            if (g[i][i] > g[p][p]) p = i;
        if (!(g[p][p] > tol)) {
            rank = c;
            break;
        }
        for (int j = 0; j < 5; j++) { /* swap rows and columns c, p */
            double t = g[c][j];
            g[c][j] = g[p][j];
            g[p][j] = t;
        }
        for (int i = 0; i < 5; i++) {
            double t = g[i][c];
            g[i][c] = g[i][p];
            g[i][p] = t;
        }
        for (int d = 0; d < 3; d++) {
            double t = r[c][d];
            r[c][d] = r[p][d];
            r[p][d] = t;
        }
        int t = perm[c];
        perm[c] = perm[p];
        perm[p] = t;
        for (int i = c + 1; i < 5; i++) {
            double f = g[i][c] / g[c][c];
            for (int j = c; j < 5; j++)
                g[i][j] -= f * g[c][j];
            for (int d = 0; d < 3; d++)
                r[i][d] -= f * r[c][d];
        }
    }
    double y[5][3] = {{0}};
    for (int i = rank - 1; i >= 0; i--)
        for (int d = 0; d < 3; d++) {
            double s = r[i][d];
            for (int j = i + 1; j < rank; j++)
                s -= g[i][j] * y[j][d];
            y[i][d] = s / g[i][i];
        }
    for (int i = 0; i < 5; i++)
        memcpy(z[perm[i]], y[i], sizeof y[i]);
    return rank;
}

/* Least displacement x = x_old + A^T (A A^T)^-1 (b - A x_old), coordinate by coordinate (the
 * equations have scalar coefficients). Returns the rank of A (5 when independent). */
static int min_displacement(double a[5][6], double b[5][3], double x[6][3], double tol)
{
    double g[5][5], r[5][3], z[5][3], scale = 0;
    for (int i = 0; i < 5; i++) {
        for (int j = 0; j < 5; j++) {
            g[i][j] = 0;
            for (int c = 0; c < 6; c++)
                g[i][j] += a[i][c] * a[j][c];
        }
        scale = fmax(scale, g[i][i]);
        for (int d = 0; d < 3; d++) {
            r[i][d] = b[i][d];
            for (int c = 0; c < 6; c++)
                r[i][d] -= a[i][c] * x[c][d];
        }
    }
    int rank = solve_gram(g, r, tol * scale, z);
    for (int c = 0; c < 6; c++)
        for (int d = 0; d < 3; d++)
            for (int i = 0; i < 5; i++)
                x[c][d] += a[i][c] * z[i][d];
    return rank;
}

static void project(const double *p, const double *o, const double *n, double *out)
{
    double d[3];
    g1_sub(p, o, d);
    double s = g1_dot(d, n);
    for (int k = 0; k < 3; k++)
        out[k] = p[k] - s * n[k];
}

/* The end triple at m in the frame of M3 (as surface.c's solve_edge does for eq. 9.3d),
 * turned into eq. 9.3d's (e1, f1, g1) and scaled so (f1, g1) is closest to (f0, g0). The
 * M3-frame coefficient of Y - m is e3 + shift: shift is the one free multiplier at m that
 * solve_edge searches on rank-deficient edges (docs/smooth.md, "the midpoint multiplier"). */
static int end_at_midpoint(const double *m, const double *y, const double *nl, const double *nr,
                           const double *n, const double *c0, double shift, double *c1)
{
    double back[3], l3[3], r3[3], e3;
    g1_sub(y, m, back);
    g1_sub(nl, m, l3);
    g1_sub(nr, m, r3);
    if (!g1_edge_coefficients(back, l3, r3, n, &e3, &c1[1], &c1[2])) return 0;
    c1[0] = -(e3 + shift + c1[1] + c1[2]);
    double rho = (c0[1] * c1[1] + c0[2] * c1[2]) / (c1[1] * c1[1] + c1[2] * c1[2]);
    if (rho > 0 && isfinite(rho))
        for (int k = 0; k < 3; k++)
            c1[k] *= rho;
    return 1;
}

static const double half[3][3] = {{0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
static const double third[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
static const double unit[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

/* K: the point after vertex `at` (0..2) of t on its edge towards side `fwd` (1: edge at, else
 * edge at - 1) when that edge is split at domain distance `frac` from the vertex, i.e. the
 * first de Casteljau point V + frac (E - V) of the boundary cubic. */
static void k_point(const fl_mesh *m, const six_tri *T, size_t t, int at, int fwd, double frac,
                    double *out)
{
    const double *v = m->xyz + 3 * m->tri[3 * t + (size_t)at];
    const double *e;
    if (fwd)
        e = T->net[at == 0 ? ix(2, 1) : at == 1 ? ix(0, 2) : ix(1, 0)];
    else
        e = T->net[at == 0 ? ix(2, 0) : at == 1 ? ix(1, 2) : ix(0, 1)];
    for (int d = 0; d < 3; d++)
        out[d] = v[d] + frac * (e[d] - v[d]);
}

/* What solve_edge knows about one macro edge before step 5: the end triples at the vertices
 * (ca, cb), the configuration at m from which the triples at m are taken, the known points. */
/* Gram pivots below RANK_TOL times the largest diagonal count as zero (a dependent edge). */
#define RANK_TOL 1e-12
/* A relative step-5 residual below RES_TOL counts as consistent (G1 to rounding). */
#define RES_TOL 1e-13

typedef struct edge_setup {
    double m[3], y0[3], yb0[3], ylp[3], yrp[3], nm[3], ca[3], cb[3], ka[3], kb[3], lam;
    const double *A, *B, *tn[2], *un[2];
} edge_setup;

/* The five vector equations of step 5 (eq. 9.3 on both half-edges, C3 at m once) with the
 * midpoint multiplier shifted by `shift`, solved for the least displacement from x0 into x;
 * *res = the largest equation residual relative to the largest coefficient times |x0|.
 * Returns the rank, -1 when an end triple has no solution. */
static int edge_solve(const edge_setup *q, double shift, double tol, double x0[6][3],
                      double x[6][3], double *res)
{
    double cma[3], cmb[3], lam = q->lam, rho = (1 - lam) / lam;
    /* both halves describe the same configuration at m: Y_B - m = -rho (Y_A - m) (C1 across
     * the midpoint spokes with m at domain position lam), so the B half's coefficient of
     * Y_B - m moves by -shift / rho */
    if (!end_at_midpoint(q->m, q->y0, q->ylp, q->yrp, q->nm, q->ca, shift, cma) ||
        !end_at_midpoint(q->m, q->yb0, q->ylp, q->yrp, q->nm, q->cb, -shift / rho, cmb))
        return -1;
    /* unknowns: 0 Y_A, 1 m, 2 P(t, A side), 3 P(u, A side), 4 P(t, B side), 5 P(u, B side);
     * the midpoint spoke points are N_m = (1 - lam) P_A + lam P_B on both sides */
    lin Ya = var2(0, 1, 0, 0), M = var2(1, 1, 1, 0), Yb = var2(1, 1 + rho, 0, -rho);
    lin NL = var2(2, 1 - lam, 4, lam), NR = var2(3, 1 - lam, 5, lam);
    lin ma[4] = {known(q->A), known(q->ka), Ya, M}, mb[4] = {known(q->B), known(q->kb), Yb, M};
    lin la[3] = {known(q->tn[0]), var2(2, 1, 2, 0), NL};
    lin ra[3] = {known(q->un[0]), var2(3, 1, 3, 0), NR};
    lin lb[3] = {known(q->tn[1]), var2(4, 1, 4, 0), NL};
    lin rb[3] = {known(q->un[1]), var2(5, 1, 5, 0), NR};
    double a[5][6] = {{0}}, b[5][3] = {{0}};
    half_edge_rows(ma, la, ra, q->ca, cma, a, b);
    half_edge_rows(mb, lb, rb, q->cb, cmb, a + 2, b + 2);
    /* C3 at m (eq. 9.3d); the B half's C3 is the same relation of the same four points. */
    acc(a[4], b[4], cma[0], &M, &Ya);
    acc(a[4], b[4], cma[1], &NL, &Ya);
    acc(a[4], b[4], cma[2], &NR, &Ya);
    memcpy(x, x0, 6 * sizeof x[0]);
    int rank = min_displacement(a, b, x, tol);
    if (rank == 5) min_displacement(a, b, x, tol); /* one step of iterative refinement */
    double worst = 0, amax = 0, xmax = 0;
    for (int i = 0; i < 5; i++)
        for (int d = 0; d < 3; d++) {
            double r = b[i][d];
            for (int c = 0; c < 6; c++) {
                r -= a[i][c] * x[c][d];
                amax = fmax(amax, fabs(a[i][c]));
                xmax = fmax(xmax, fabs(x0[c][d]));
            }
            worst = fmax(worst, fabs(r));
        }
    *res = worst / (amax * fmax(xmax, 1e-300));
    if (!isfinite(*res)) *res = INFINITY;
    return rank;
}

static double displacement(double x0[6][3], double x[6][3]);
static double spoke_ratio(double lam, double x0[6][3], double x[6][3]);

/* A solution is kept only near the subdivision values: the midpoint spokes within 1/4..4 of
 * their subdivision length and no point moved more than half the edge length. sphere.off and
 * elephant.off have edges whose only roots stretch the spokes 14-20000 times (sphere.off then
 * bulges to 2900 mean edge lengths). */
static int near_solution(const edge_setup *q, double x0[6][3], double x[6][3])
{
    double ab[3], sr = spoke_ratio(q->lam, x0, x);
    g1_sub(q->B, q->A, ab);
    return sr >= 0.25 && sr <= 4 && sqrt(displacement(x0, x)) <= 0.5 * g1_length(ab);
}

/* A rank-deficient edge (a mirror plane through the edge makes f = g on both halves, so the
 * equations see the two micro centres beside each half only through their sum: 4 unknown
 * points for 5 equations) is in general inconsistent with the multipliers taken from the
 * subdivision values at m. The coefficient of Y - m in the triple at m is one scalar the
 * construction is free to choose (the shape of the configuration at m, any value keeps the
 * four points coplanar); for one value the system is consistent. Measured on the once
 * subdivided icosahedron's degree-5/degree-6 edges: the residual vanishes linearly (|r| ~
 * |shift - shift*|) at one shift, with the midpoint spokes non-degenerate. We bracket it on a
 * coarse grid and refine by golden section; x keeps the best solution found. */
static double midpoint_multiplier_search(const edge_setup *q, double x0[6][3], double x[6][3],
                                         double res0)
{
    enum { GRID = 40 };
    const double lo = -0.5, hi = 0.5, step = (hi - lo) / GRID, g = 0.6180339887498949;
    double grid[GRID + 1], y[6][3], r, best = res0, pick[6][3];
    int found = 0;
    for (int i = 0; i <= GRID; i++)
        if (edge_solve(q, lo + step * i, RANK_TOL, x0, y, &grid[i]) < 0) grid[i] = INFINITY;
    /* The residual can have several roots; refine around every grid minimum and keep the most
     * accurate solution that stays near the subdivision values (sphere.off and elephant.off
     * have far roots whose solutions stretch the midpoint spokes 14-20000 times). */
    for (int i = 0; i <= GRID; i++) {
        if (!(grid[i] < res0) || (i > 0 && grid[i - 1] < grid[i]) ||
            (i < GRID && grid[i + 1] < grid[i]))
            continue;
        double a = lo + step * (i - 1), b = lo + step * (i + 1), bt = lo + step * i,
               bv = grid[i], rc, rd;
        for (int it = 0; it < 80 && bv > 1e-16; it++) {
            double c = b - g * (b - a), d = a + g * (b - a);
            if (edge_solve(q, c, RANK_TOL, x0, y, &rc) < 0) rc = INFINITY;
            if (edge_solve(q, d, RANK_TOL, x0, y, &rd) < 0) rd = INFINITY;
            if (rc < rd) b = d; else a = c;
            if (fmin(rc, rd) < bv) bv = fmin(rc, rd), bt = rc < rd ? c : d;
        }
        double z[6][3];
        edge_solve(q, bt, RANK_TOL, x0, z, &r);
        /* On a nearly (not exactly) symmetric edge the rank-4 solve leaves the small equation
         * it dropped unsatisfied (residual ~1e-12 on elephant.off); with the multiplier found
         * the full system is nearly consistent, so its full-rank solution stays close: take it
         * when it is more accurate and moves the points at most twice as far. */
        double rz = r;
        if (edge_solve(q, bt, 1e-24, x0, y, &r) == 5 && r < rz &&
            displacement(x0, y) <= 4 * displacement(x0, z))
            memcpy(z, y, sizeof y), rz = r;
        if (rz < best && near_solution(q, x0, z))
            memcpy(pick, z, sizeof z), best = rz, found = 1;
    }
    if (found) memcpy(x, pick, sizeof pick);
    return best;
}

/* Squared displacement of x from x0 (the thesis's objective, §9.8 step 5, in squares). */
static double displacement(double x0[6][3], double x[6][3])
{
    double s = 0;
    for (int c = 0; c < 6; c++)
        for (int d = 0; d < 3; d++)
            s += (x[c][d] - x0[c][d]) * (x[c][d] - x0[c][d]);
    return s;
}

/* The smaller of the two midpoint spokes |Nm - m| (T's and U's) relative to the same spoke
 * in x0: how far the solution x has collapsed the corner at m. */
static double spoke_ratio(double lam, double x0[6][3], double x[6][3])
{
    double worst = INFINITY;
    for (int side = 0; side < 2; side++) {
        double a = 0, b = 0;
        for (int d = 0; d < 3; d++) {
            double s1 = (1 - lam) * x[2 + side][d] + lam * x[4 + side][d] - x[1][d];
            double s0 = (1 - lam) * x0[2 + side][d] + lam * x0[4 + side][d] - x0[1][d];
            a += s1 * s1;
            b += s0 * s0;
        }
        if (!(b > 0)) return INFINITY; /* no spoke to keep (or NaN input): nothing to search */
        worst = fmin(worst, sqrt(a / b));
    }
    return worst;
}

/* On an independent edge every midpoint multiplier gives a consistent system, but the one
 * taken from the subdivision values can be the worst choice: on the once subdivided
 * icosahedron's degree-6/degree-6 edges (a mirror plane across the edge) its solution drives
 * both midpoint spokes onto m (|Nm - m| ~ 1e-14: a degenerate corner, normals there jump by
 * ~1 degree), and a shift of +-0.03 gives |Nm - m| = 0.057, about the subdivision value. Where
 * the spokes shrink below half their subdivision length we take, among the shifts that keep
 * them at least that long, the one of least displacement from the subdivision values (the
 * thesis's objective, §9.8 step 5): a grid, then bisection towards the collapse, since the
 * displacement grows away from it. Any shift keeps the edge G1; only the shape changes. */
static void midpoint_spoke_search(const edge_setup *q, double x0[6][3], double x[6][3])
{
    enum { GRID = 80 };
    const double lo = -0.5, hi = 0.5, step = (hi - lo) / GRID, keep = 0.5;
    if (spoke_ratio(q->lam, x0, x) >= keep) return;
    double best = INFINITY, bt = 0, y[6][3], r;
    for (int i = 0; i <= GRID; i++) {
        double t = lo + step * i, v;
        if (edge_solve(q, t, RANK_TOL, x0, y, &r) == 5 && r < 1e-13 &&
            spoke_ratio(q->lam, x0, y) >= keep && (v = displacement(x0, y)) < best)
            best = v, bt = t;
    }
    if (!(best < INFINITY)) return;
    /* towards the neighbour with the smaller displacement, stopping where the spokes would
     * fall below `keep` */
    double in = bt, out = INFINITY, vn = INFINITY;
    for (int sgn = -1; sgn <= 1; sgn += 2) {
        double t = bt + sgn * step, v;
        if (edge_solve(q, t, RANK_TOL, x0, y, &r) == 5 && r < 1e-13 &&
            (v = displacement(x0, y)) < vn)
            vn = v, out = t;
    }
    if (vn < best)
        for (int it = 0; it < 50; it++) {
            double t = (in + out) / 2;
            if (edge_solve(q, t, RANK_TOL, x0, y, &r) == 5 && r < 1e-13 &&
                spoke_ratio(q->lam, x0, y) >= keep && displacement(x0, y) <= best)
                in = t, best = displacement(x0, y);
            else
                out = t;
        }
    if (edge_solve(q, in, RANK_TOL, x0, y, &r) == 5 && r < 1e-13) memcpy(x, y, sizeof y);
}

/* One macro edge for step 5: half-edge h = 3t + k of triangle T and its twin 3u + j of U. */
typedef struct edge_ctx {
    const fl_mesh *mesh;
    const double *normals;
    six_tri *T, *U;
    size_t t, u;
    int k, j;
} edge_ctx;

/* The known data of step 5 with the edge split at domain position lam from A (q) and the
 * subdivision values of the six unknowns at that split (x0): m = P(lam), Y_A and the four
 * micro centres are blossoms of the macro patches (§9.5), the end triples at A and B come from
 * the vertex tangent planes (eq. 9.3a), the configuration at m from the plane there. Returns 0
 * when a tangent plane is undefined. */
static int edge_prepare(const edge_ctx *c, double lam, edge_setup *q, double x0[6][3])
{
    const fl_mesh *m = c->mesh;
    const six_tri *T = c->T, *U = c->U;
    int k = c->k, j = c->j, k1 = (k + 1) % 3, j1 = (j + 1) % 3;
    double mk[3], mj[3], nt[3], nu[3], nl0[3], nr0[3], rho = (1 - lam) / lam;
    for (int i = 0; i < 3; i++) {
        mk[i] = (1 - lam) * unit[k][i] + lam * unit[k1][i];
        mj[i] = lam * unit[j][i] + (1 - lam) * unit[j1][i]; /* the same point of the edge */
    }
    memset(q, 0, sizeof *q);
    q->lam = lam;
    q->A = m->xyz + 3 * m->tri[3 * c->t + (size_t)k];
    q->B = m->xyz + 3 * m->tri[3 * c->t + (size_t)k1];
    k_point(m, T, c->t, k, 1, lam, q->ka);
    k_point(m, T, c->t, k1, 0, 1 - lam, q->kb);
    g1_blossom(T->net, mk, mk, mk, x0[1]);
    g1_blossom(T->net, unit[k], mk, mk, x0[0]);
    g1_blossom(T->net, unit[k], mk, third, x0[2]);
    g1_blossom(U->net, mj, unit[j1], third, x0[3]);
    g1_blossom(T->net, mk, unit[k1], third, x0[4]);
    g1_blossom(U->net, unit[j], mj, third, x0[5]);
    /* the tangent plane at m: mean of the two macro patches' normals there */
    double tn[10][3], un[10][3];
    memcpy(tn, T->net, sizeof tn);
    memcpy(un, U->net, sizeof un);
    fl_g1_patch_eval(&tn[0][0], mk[0], mk[1], mk[2], NULL, nt);
    fl_g1_patch_eval(&un[0][0], mj[0], mj[1], mj[2], NULL, nu);
    for (int d = 0; d < 3; d++) {
        q->nm[d] = nt[d] + nu[d];
        nl0[d] = (1 - lam) * x0[2][d] + lam * x0[4][d];
        nr0[d] = (1 - lam) * x0[3][d] + lam * x0[5][d];
    }
    if (!(g1_normalize(q->nm) > 1e-12)) return 0;
    memcpy(q->m, x0[1], sizeof q->m);
    project(x0[0], x0[1], q->nm, q->y0);
    project(nl0, x0[1], q->nm, q->ylp);
    project(nr0, x0[1], q->nm, q->yrp);
    for (int d = 0; d < 3; d++)
        q->yb0[d] = x0[1][d] - rho * (q->y0[d] - x0[1][d]);
    q->tn[0] = T->n[k];
    q->tn[1] = T->n[k1];
    q->un[0] = U->n[j1];
    q->un[1] = U->n[j];
    double d0[3], l0[3], r0[3];
    g1_sub(q->ka, q->A, d0);
    g1_sub(q->tn[0], q->A, l0);
    g1_sub(q->un[0], q->A, r0);
    if (!g1_edge_coefficients(d0, l0, r0, c->normals + 3 * m->tri[3 * c->t + (size_t)k],
                              &q->ca[0], &q->ca[1], &q->ca[2]))
        return 0;
    g1_sub(q->kb, q->B, d0);
    g1_sub(q->tn[1], q->B, l0);
    g1_sub(q->un[1], q->B, r0);
    return g1_edge_coefficients(d0, l0, r0, c->normals + 3 * m->tri[3 * c->t + (size_t)k1],
                                &q->cb[0], &q->cb[1], &q->cb[2]);
}

/* A nearly (not exactly) dependent edge (elephant.off: rank 3-4 at RANK_TOL, residual
 * 1e-12..1e-9 at every shift and ratio) is consistent as a full-rank system; its exact
 * solution is kept when it stays near the subdivision values, the one of least displacement
 * over the shifts of the midpoint multiplier (a 41-point grid). Returns the residual of x. */
static double full_rank_search(const edge_setup *q, double x0[6][3], double x[6][3], double res)
{
    enum { GRID = 40 };
    double y[6][3], r, best = INFINITY;
    for (int i = 0; i <= GRID; i++) {
        double d;
        if (edge_solve(q, -0.5 + (double)i / GRID, 1e-24, x0, y, &r) == 5 && r <= RES_TOL &&
            near_solution(q, x0, y) && (d = displacement(x0, y)) < best)
            best = d, res = r, memcpy(x, y, sizeof y);
    }
    return res;
}

/* Step 5 at split ratio lam: the solve with the subdivision multiplier at m, then the searches
 * of the multiplier. x = the solution, *res its relative residual. Returns the rank (-1: no
 * tangent plane). */
static int edge_at_ratio(const edge_ctx *c, double lam, double x[6][3], double *res)
{
    edge_setup q;
    double x0[6][3];
    if (!edge_prepare(c, lam, &q, x0)) return -1;
    int rank = edge_solve(&q, 0, RANK_TOL, x0, x, res);
    if (rank < 0) return -1;
    if (rank < 5 && *res > RES_TOL) *res = midpoint_multiplier_search(&q, x0, x, *res);
    if (rank < 5 && *res > RES_TOL) *res = full_rank_search(&q, x0, x, *res);
    if (rank == 5) midpoint_spoke_search(&q, x0, x);
    return rank;
}

/* near_solution for x solved at split ratio lam. */
static int near_at_ratio(const edge_ctx *c, double lam, double x[6][3])
{
    edge_setup q;
    double x0[6][3];
    return edge_prepare(c, lam, &q, x0) && near_solution(&q, x0, x);
}

/* Where no midpoint multiplier makes a rank-deficient edge consistent at lam = 1/2 (the twice
 * subdivided icosahedron, sphere.off: the residual over the shift has a positive minimum, its
 * three coordinates vanish at different shifts), or the solution there is far from the
 * subdivision values (sphere.off: full-rank edges moved 6-8 edge lengths), the split ratio lam of the macro edge is the
 * second free number (docs/smooth.md, "the split ratio"): moving m in the domain changes the
 * C1 relations at m (Y_B - m = -((1 - lam) / lam)(Y_A - m), N_m = (1 - lam) P_A + lam P_B) and
 * the subdivision values, nothing outside the edge's two triangles. Measured on the twice
 * subdivided icosahedron: consistent solutions (residual ~1e-16, displacement 0.1-0.3 % of the
 * edge, spokes within 1 % of their subdivision length) exist on an interval of lam ending
 * 0.12-0.16 from 1/2, on one side only. We walk outwards from 1/2 in steps of 1/100 and take
 * the first consistent ratio (the nearer to the symmetric split; of two at the same distance
 * the one of less displacement from its subdivision values), then bisect towards 1/2 to the
 * end of the consistent interval. x, *lam and *res are replaced only when one is found. */
static void split_ratio_search(const edge_ctx *c, double x[6][3], double *lam, double *res)
{
    enum { STEPS = 40, BISECT = 12 };
    const double step = 0.01;
    double y[6][3], r, best[6][3], bl = 0.5, bd = INFINITY;
    int i = 1;
    for (; i <= STEPS && !(bd < INFINITY); i++)
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double l = 0.5 + sgn * step * i, x0[6][3];
            edge_setup q;
            if (edge_at_ratio(c, l, y, &r) < 0 || !(r <= RES_TOL) || !edge_prepare(c, l, &q, x0) ||
                !near_solution(&q, x0, y))
                continue;
            double d = displacement(x0, y);
            if (d < bd) bd = d, bl = l, memcpy(best, y, sizeof y);
        }
    if (!(bd < INFINITY)) return;
    double in = bl, out = 0.5 + (bl - 0.5) * (i - 2) / (i - 1); /* the inconsistent neighbour */
    for (int it = 0; it < BISECT; it++) {
        double l = (in + out) / 2;
        if (edge_at_ratio(c, l, y, &r) >= 0 && r <= RES_TOL && near_at_ratio(c, l, y))
            in = l, memcpy(best, y, sizeof y);
        else
            out = l;
    }
    memcpy(x, best, sizeof best);
    *lam = in;
    *res = 0; /* below RES_TOL */
}

/* Step 5 on the macro edge of half-edge h (triangle t, edge k) and its twin (u, edge j):
 * the symmetric split first, the split ratio only where no multiplier makes it consistent
 * near the subdivision values. */
static int solve_edge(const fl_mesh *m, const double *normals, six_tri *tris, six_edge *edges,
                      size_t h, size_t h2)
{
    edge_ctx c = {m, normals, tris + h / 3, tris + h2 / 3, h / 3, h2 / 3, (int)(h % 3),
                  (int)(h2 % 3)};
    double x[6][3], res = 0, lam = 0.5;
    int rank = edge_at_ratio(&c, lam, x, &res);
    if (rank < 0) return -1;
    if (res > RES_TOL || !near_at_ratio(&c, lam, x)) split_ratio_search(&c, x, &lam, &res);
    six_tri *T = c.T, *U = c.U;
    int k = c.k, j = c.j;
    double rho = (1 - lam) / lam;
    six_edge *E = edges + h, *F = edges + h2;
    memcpy(E->m, x[1], sizeof E->m);
    memcpy(E->ya, x[0], sizeof E->ya);
    for (int d = 0; d < 3; d++)
        E->yb[d] = x[1][d] - rho * (x[0][d] - x[1][d]);
    E->lam = lam;
    F->lam = 1 - lam;
    memcpy(F->m, E->m, sizeof F->m);
    memcpy(F->ya, E->yb, sizeof F->ya);
    memcpy(F->yb, E->ya, sizeof F->yb);
    memcpy(T->p[2 * k], x[2], sizeof x[2]);
    memcpy(U->p[2 * j + 1], x[3], sizeof x[3]);
    memcpy(T->p[2 * k + 1], x[4], sizeof x[4]);
    memcpy(U->p[2 * j], x[5], sizeof x[5]);
    return rank < 5;
}

/* Steps 1-4 for triangle t: macro net, vertex-spoke points N (eq. 9.14 with b = -2/3) and the
 * subdivision values of the six centres. ep holds the shared boundary edge points. */
static void macro_six(const fl_mesh *m, const double (*ep)[2][3], size_t t, six_tri *T)
{
    const uint32_t *v = m->tri + 3 * t;
    double se[3] = {0, 0, 0}, sv[3] = {0, 0, 0};
    const int at[3][2] = {{ix(2, 1), ix(1, 2)}, {ix(0, 2), ix(0, 1)}, {ix(1, 0), ix(2, 0)}};
    for (int k = 0; k < 3; k++) {
        memcpy(T->net[k == 0 ? ix(3, 0) : k == 1 ? ix(0, 3) : ix(0, 0)], m->xyz + 3 * v[k],
               3 * sizeof(double));
        memcpy(T->net[at[k][0]], ep[3 * t + (size_t)k][0], 3 * sizeof(double));
        memcpy(T->net[at[k][1]], ep[3 * t + (size_t)k][1], 3 * sizeof(double));
        for (int d = 0; d < 3; d++) {
            se[d] += ep[3 * t + (size_t)k][0][d] + ep[3 * t + (size_t)k][1][d];
            sv[d] += m->xyz[3 * v[k] + d];
        }
    }
    for (int d = 0; d < 3; d++)
        T->net[ix(1, 1)][d] = se[d] / 4 - sv[d] / 6;
    for (int k = 0; k < 3; k++) {
        double kf[3], kbk[3];
        k_point(m, T, t, k, 1, 0.5, kf);
        k_point(m, T, t, k, 0, 0.5, kbk);
        for (int d = 0; d < 3; d++)
            T->n[k][d] = 2.0 / 3 * (kf[d] + kbk[d]) - m->xyz[3 * v[k] + d] / 3;
        g1_blossom(T->net, unit[k], half[k], third, T->p[2 * k]);
        g1_blossom(T->net, half[k], unit[(k + 1) % 3], third, T->p[2 * k + 1]);
    }
}

static void put(double *ctrl, int i, int j, const double *p)
{
    memcpy(ctrl + 3 * ix(i, j), p, 3 * sizeof(double));
}

/* Steps 6-7 and the six micro patches of triangle t. */
static void emit_six(const fl_mesh *m, const six_tri *T, const six_edge *edges,
                     const uint32_t *edge_id, size_t t, fl_g1_surface *s)
{
    const uint32_t *v = m->tri + 3 * t;
    double q[3][3], qm[3][3], nmid[3][3], o[3] = {0, 0, 0}, lam[3];
    for (int i = 0; i < 3; i++)
        lam[i] = edges[3 * t + (size_t)i].lam;
    for (int i = 0; i < 3; i++) {
        /* C1 across the vertex spoke V_i -> O: the split point of the previous edge is
         * m_i-1 = a V_i + b m_i + c O in the macro domain (m_i at lam_i from V_i, m_i-1 at
         * lam_i-1 from V_i-1), so P_2i-1 = a N_i + b P_2i + c Q_i; lam = 1/2 gives eq. 9.13a */
        int prev = (2 * i + 5) % 6;
        double lp = lam[(i + 2) % 3], cc = 3 * (1 - lp), bb = -(1 - lp) / lam[i],
               aa = 1 - bb - cc;
        for (int d = 0; d < 3; d++) {
            q[i][d] = (T->p[prev][d] - aa * T->n[i][d] - bb * T->p[2 * i][d]) / cc;
            nmid[i][d] = (1 - lam[i]) * T->p[2 * i][d] + lam[i] * T->p[2 * i + 1][d];
            o[d] += q[i][d] / 3;
        }
    }
    for (int i = 0; i < 3; i++) /* C1 across the midpoint spoke m_i -> O (eq. 9.12b) */
        for (int d = 0; d < 3; d++)
            qm[i][d] = (1 - lam[i]) * q[i][d] + lam[i] * q[(i + 1) % 3][d];
    uint32_t centre = (uint32_t)(m->vertex_count + t);
    for (int i = 0; i < 3; i++) {
        int i1 = (i + 1) % 3;
        size_t h = 3 * t + (size_t)i;
        const six_edge *E = edges + h;
        uint32_t mid = (uint32_t)(m->vertex_count + m->triangle_count + edge_id[h]);
        double kf[3], kb[3];
        k_point(m, T, t, i, 1, lam[i], kf);
        k_point(m, T, t, i1, 0, 1 - lam[i], kb);
        size_t p0 = 6 * t + 2 * (size_t)i, p1 = p0 + 1;
        double *c = s->ctrl + 30 * p0;
        put(c, 3, 0, m->xyz + 3 * v[i]);
        put(c, 2, 1, kf);
        put(c, 1, 2, E->ya);
        put(c, 0, 3, E->m);
        put(c, 2, 0, T->n[i]);
        put(c, 1, 1, T->p[2 * i]);
        put(c, 0, 2, nmid[i]);
        put(c, 1, 0, q[i]);
        put(c, 0, 1, qm[i]);
        put(c, 0, 0, o);
        s->corner[3 * p0] = v[i];
        s->corner[3 * p0 + 1] = mid;
        s->corner[3 * p0 + 2] = centre;
        c = s->ctrl + 30 * p1;
        put(c, 3, 0, E->m);
        put(c, 2, 1, E->yb);
        put(c, 1, 2, kb);
        put(c, 0, 3, m->xyz + 3 * v[i1]);
        put(c, 2, 0, nmid[i]);
        put(c, 1, 1, T->p[2 * i + 1]);
        put(c, 0, 2, T->n[i1]);
        put(c, 1, 0, qm[i]);
        put(c, 0, 1, q[i1]);
        put(c, 0, 0, o);
        s->corner[3 * p1] = mid;
        s->corner[3 * p1 + 1] = v[i1];
        s->corner[3 * p1 + 2] = centre;
        s->macro[p0] = s->macro[p1] = (uint32_t)t;
    }
}

fl_status g1_six_split(const fl_mesh *m, const double *normals, const double *tan,
                       double tension, fl_g1_surface *s, fl_error *err)
{
    size_t nt = m->triangle_count;
    uint32_t *opp = NULL;
    fl_status st = g1_opposite_half_edges(m, &opp, err);
    if (st) return st;
    double(*ep)[2][3] = fl_alloc_array(3 * nt, sizeof *ep);
    six_tri *tris = fl_alloc_array(nt, sizeof *tris);
    six_edge *edges = fl_alloc_array(3 * nt, sizeof *edges);
    uint32_t *edge_id = fl_alloc_array(3 * nt, sizeof *edge_id);
    if (!ep || !tris || !edges || !edge_id) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
        goto done;
    }
    /* step 2, once an edge so both triangles hold bit-identical boundary curves */
    uint32_t ne = 0;
    for (size_t h = 0; h < 3 * nt; h++) {
        if (opp[h] < h) continue;
        uint32_t a = m->tri[h], b = m->tri[3 * (h / 3) + (h + 1) % 3];
        g1_edge_point(m->xyz + 3 * a, tan + 3 * h, tension, ep[h][0]);
        g1_edge_point(m->xyz + 3 * b, tan + 3 * (size_t)opp[h], tension, ep[h][1]);
        memcpy(ep[opp[h]][0], ep[h][1], sizeof ep[h][1]);
        memcpy(ep[opp[h]][1], ep[h][0], sizeof ep[h][0]);
        edge_id[h] = edge_id[opp[h]] = ne++;
    }
    s->node_count = m->vertex_count + nt + ne;
    for (size_t t = 0; t < nt; t++)
        macro_six(m, (const double(*)[2][3])ep, t, tris + t);
    s->singular_edges = 0;
    for (size_t h = 0; h < 3 * nt; h++) {
        if (opp[h] < h) continue;
        int r = solve_edge(m, normals, tris, edges, h, opp[h]);
        if (r < 0) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                         "six-split: no tangent plane at a vertex or edge midpoint (two "
                         "triangles project onto one line there)");
            goto done;
        }
        s->singular_edges += (size_t)r;
    }
    for (size_t t = 0; t < nt; t++)
        emit_six(m, tris + t, edges, edge_id, t, s);
done:
    free(opp);
    free(ep);
    free(tris);
    free(edges);
    free(edge_id);
    return st;
}

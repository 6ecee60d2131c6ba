/* Symbolic perturbation (Simulation of Simplicity) on top of the exact predicates.
 *
 * All determinants here are of the matrix whose row k is (p_k, [lift_k,] 1) in argument
 * order: det[p 1] is orient2d/orient3d and det[p l 1] is incircle/insphere (subtracting the
 * last row from the others gives the difference forms evaluated in predicates.c).
 *
 * Orientation: Edelsbrunner & Mucke, "Simulation of Simplicity" (ACM TOG 9(1), 1990), §4-5.
 * Coordinate j of the point with index i becomes p_ij + eps^(2^kappa(i,j)) with
 * kappa = i*d + (d-1-j). det is multilinear in the rows, so the perturbed determinant is a sum
 * over partial matchings S = {(row, column)} (distinct rows, distinct columns) of
 * prod_S eps^(2^kappa) times det(matrix with the rows of S replaced by unit vectors e_column).
 * The monomial of S is eps^(sum of 2^kappa over S) and distinct S have distinct exponents
 * (binary representations), so ordering S by that exponent - i.e. by the bitmask of its kappas
 * read as an integer - orders the terms by decreasing magnitude, and the first nonzero
 * coefficient decides. Only the relative order of the kappas matters, so ranks of the indices
 * among the call's points stand for the indices themselves.
 *
 * In-circle / in-sphere: Devillers & Teillaud, "Perturbations and vertex removal in a 3D
 * Delaunay triangulation" (SODA 2003), §3. Only the lift column is perturbed:
 * l_k -> l_k - eps_k (weight + eps_k), with eps_k larger for a higher index. det is linear in
 * that column, so det(eps) = det - sum_k eps_k C_k with the cofactor
 * C_k = (-1)^(k + d) det[p 1] over the other points, i.e. (-1)^(k+d) times their orientation. */
#include "predicates/predicates_internal.h"
#include "flintstone.h"

/* Sign of det[q 1] for the points left after deleting the rows in rowmask and the coordinate
 * columns in colmask: an orientation in dimension d - |colmask| < d. */
static int projected_orientation(const double *const *pts, int n, int d, int rowmask, int colmask)
{
    double q[4][3];
    int rows = 0, dims = 0;
    for (int r = 0; r < n; r++) {
        if (rowmask >> r & 1) continue;
        dims = 0;
        for (int j = 0; j < d; j++)
            if (!(colmask >> j & 1)) q[rows][dims++] = pts[r][j];
        rows++;
    }
    if (dims == 0) return 1;                                         /* det[[1]] */
    if (dims == 1) return (q[0][0] > q[1][0]) - (q[0][0] < q[1][0]); /* det[[x0 1],[x1 1]] */
    return fl_orient2d(q[0], q[1], q[2]);
}

/* Index order: row_of_rank[r] is the row holding the r-th smallest index. */
static void rank_rows(const uint32_t *idx, int n, int *row_of_rank)
{
    for (int i = 0; i < n; i++)
        row_of_rank[i] = i;
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && idx[row_of_rank[j - 1]] > idx[row_of_rank[j]]; j--) {
            int t = row_of_rank[j];
            row_of_rank[j] = row_of_rank[j - 1];
            row_of_rank[j - 1] = t;
        }
}

/* The coefficient of the matching encoded by `mask` (bit kappa = rank*d + d-1-j), or 0 when
 * the mask is not a matching. Generalized Laplace expansion along the replaced rows R:
 * coefficient = sgn(sigma) (-1)^(sum R + sum C) det(rest), sigma the order of the columns read
 * along ascending rows. */
static int matching_coefficient(const double *const *pts, int n, int d, const int *row_of_rank,
                                unsigned mask)
{
    int col_of_row[4] = {-1, -1, -1, -1}, rowmask = 0, colmask = 0, parity = 0;
    for (int kappa = 0; mask >> kappa; kappa++) {
        if (!(mask >> kappa & 1)) continue;
        int r = row_of_rank[kappa / d], c = d - 1 - kappa % d;
        if ((rowmask >> r & 1) || (colmask >> c & 1)) return 0;
        rowmask |= 1 << r;
        colmask |= 1 << c;
        col_of_row[r] = c;
        parity += r + c;
    }
    int prev[4], k = 0;
    for (int r = 0; r < n; r++) {
        if (col_of_row[r] < 0) continue;
        for (int i = 0; i < k; i++)
            parity += prev[i] > col_of_row[r]; /* inversions of sigma */
        prev[k++] = col_of_row[r];
    }
    int s = projected_orientation(pts, n, d, rowmask, colmask);
    return (parity & 1) ? -s : s;
}

/* Decides a zero orientation determinant of n = d + 1 points. A full matching (d rows) leaves
 * det[[1]] = 1, so the loop always returns nonzero. */
static int orientation_sos(const double *const *pts, const uint32_t *idx, int n, int d)
{
    int row_of_rank[4];
    rank_rows(idx, n, row_of_rank);
    for (unsigned mask = 1; mask < (1u << (n * d)); mask++) {
        int s = matching_coefficient(pts, n, d, row_of_rank, mask);
        if (s) return s;
    }
    return 0; /* unreachable for distinct indices */
}

/* Decides a zero in-circle / in-sphere determinant of n = d + 2 points: the highest index
 * first, the first nonzero cofactor -C_k decides. */
static int lift_sos(const double *const *pts, const uint32_t *idx, int n, int d)
{
    int row_of_rank[5];
    rank_rows(idx, n, row_of_rank);
    for (int t = n - 1; t >= 0; t--) {
        int k = row_of_rank[t];
        const double *o[4];
        for (int r = 0, m = 0; r < n; r++)
            if (r != k) o[m++] = pts[r];
        int s = d == 2 ? fl_orient2d(o[0], o[1], o[2]) : fl_orient3d(o[0], o[1], o[2], o[3]);
        if (s) return ((k + d) & 1) ? s : -s;
    }
    return 0; /* all points collinear (coplanar) */
}

int fl_orient2d_sos(const double *a, const double *b, const double *c, uint32_t ia, uint32_t ib,
                    uint32_t ic)
{
    int s = fl_orient2d(a, b, c);
    if (s) return s;
    const double *p[3] = {a, b, c};
    const uint32_t idx[3] = {ia, ib, ic};
    return orientation_sos(p, idx, 3, 2);
}

int fl_orient3d_sos(const double *a, const double *b, const double *c, const double *d, uint32_t ia,
                    uint32_t ib, uint32_t ic, uint32_t id)
{
    int s = fl_orient3d(a, b, c, d);
    if (s) return s;
    const double *p[4] = {a, b, c, d};
    const uint32_t idx[4] = {ia, ib, ic, id};
    return orientation_sos(p, idx, 4, 3);
}

int fl_incircle_sos(const double *a, const double *b, const double *c, const double *d, uint32_t ia,
                    uint32_t ib, uint32_t ic, uint32_t id)
{
    int s = fl_incircle(a, b, c, d);
    if (s) return s;
    const double *p[4] = {a, b, c, d};
    const uint32_t idx[4] = {ia, ib, ic, id};
    return lift_sos(p, idx, 4, 2);
}

int fl_incircle_weighted_sos(const double *a, const double *b, const double *c, const double *d,
                             uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id)
{
    int s = fl_incircle_weighted(a, b, c, d);
    if (s) return s;
    const double *p[4] = {a, b, c, d};
    const uint32_t idx[4] = {ia, ib, ic, id};
    return lift_sos(p, idx, 4, 2);
}

int fl_insphere_sos(const double *a, const double *b, const double *c, const double *d,
                    const double *e, uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id,
                    uint32_t ie)
{
    int s = fl_insphere(a, b, c, d, e);
    if (s) return s;
    const double *p[5] = {a, b, c, d, e};
    const uint32_t idx[5] = {ia, ib, ic, id, ie};
    return lift_sos(p, idx, 5, 3);
}

int fl_insphere_weighted_sos(const double *a, const double *b, const double *c, const double *d,
                             const double *e, uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id,
                             uint32_t ie)
{
    int s = fl_insphere_weighted(a, b, c, d, e);
    if (s) return s;
    const double *p[5] = {a, b, c, d, e};
    const uint32_t idx[5] = {ia, ib, ic, id, ie};
    return lift_sos(p, idx, 5, 3);
}

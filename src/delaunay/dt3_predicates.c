/* The one combinatorial test of the 3D triangulations beyond orientation: is a point in
 * conflict with a tetrahedron? Exact, with ties broken by a symbolic perturbation of the lifting.
 *
 * Lift every point p to (p, |p|^2 - w_p) in R^4 (w_p = 0 for unweighted points; skin paper §2.1,
 * the map phi). The Delaunay / regular triangulation is the projection of the lower convex hull
 * of the lifted points, and e is in conflict with tetrahedron abcd exactly when its lifted point
 * lies below the hyperplane through the lifted a, b, c, d. When it lies exactly on it we
 * perturb the heights: point i's height is raised by eps^(N - i) for an infinitesimal eps, where
 * i is the caller's index. The perturbed test is a 5x5 determinant of rows (p, height, 1) that is
 * linear in each height, so its sign is the sign of the cofactor of the highest-priority point
 * whose cofactor is not zero; each cofactor is an orientation of the other four points.
 *
 * Why the lifting and not the coordinates: a perturbation of the heights alone is a tiny
 * weighting of the exact points, so the result is a regular triangulation of the exact points.
 * It never contains a flat tetrahedron, and a point on a face shared by two tetrahedra gets the
 * same answer from both (their lifted hyperplanes agree on the lifted face), which keeps the
 * Bowyer-Watson cavity star-shaped on grids and cospherical input. This is the scheme CGAL's
 * Delaunay_triangulation_3 uses (perturbation by a total order on the points). */
#include "delaunay/dt3_internal.h"

/* Sign of the height-eps term of point slot i (0..3 for a..d, 4 for e) in the expansion of the
 * lifted determinant. Raising e's height moves it out of conflict: -orient(a, b, c, d). Swapping
 * e with a corner flips the determinant, so raising a corner's height contributes
 * +orient(abcd with that corner replaced by e). */
static int height_cofactor(const double *const p[5], int i)
{
    if (i == 4) return -fl_orient3d(p[0], p[1], p[2], p[3]);
    const double *q[4] = {p[0], p[1], p[2], p[3]};
    q[i] = p[4];
    return fl_orient3d(q[0], q[1], q[2], q[3]);
}

static int lifting_tie(const double *const p[5], const uint32_t g[5])
{
    int order[5] = {0, 1, 2, 3, 4};
    /* Insertion sort by decreasing priority: five elements. */
    for (int i = 1; i < 5; i++)
        for (int j = i; j > 0 && g[order[j]] > g[order[j - 1]]; j--) {
            int t = order[j];
            order[j] = order[j - 1];
            order[j - 1] = t;
        }
    for (int i = 0; i < 5; i++) {
        int s = height_cofactor(p, order[i]);
        if (s != 0) return s;
    }
    /* All five cofactors vanish only when the five points are coplanar, which the callers
     * exclude (abcd is a positive tetrahedron, so the cofactor of e is -1). */
    return -1;
}

int dt3_power_sos(int weighted, const double *a, const double *b, const double *c, const double *d,
                  const double *e, uint32_t ga, uint32_t gb, uint32_t gc, uint32_t gd, uint32_t ge)
{
    int s = weighted ? fl_insphere_weighted(a, b, c, d, e) : fl_insphere(a, b, c, d, e);
    if (s != 0) return s;
    const double *const p[5] = {a, b, c, d, e};
    const uint32_t g[5] = {ga, gb, gc, gd, ge};
    return lifting_tie(p, g);
}

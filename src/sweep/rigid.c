/* Queries against a shape in rigid motion (Guéziec §5.2): "for a rigid motion of the mesh the
 * sizes of the intervals are affected, but the bounding-volume hierarchy is not". The
 * hierarchy stays in the shape's own frame and the query is carried into it instead:
 * q' = Rᵀ (q − t). Distances are invariant under the motion, so the answer in the shape's
 * frame is the answer, with the closest point carried back (R p' + t). Through a cursor, a
 * moving shape is a moving query point in the shape's frame, and §5.1 (intervals widened by
 * the move, only fronts recomputed) applies unchanged; its δ, the move of q', is never more
 * than the paper's largest vertex displacement for points inside the shape's reach. */
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "sweep/sweep_internal.h"

/* How far RᵀR may be from the identity (largest entry): an R this close to orthonormal moves
 * distances by at most about this much relative, within the accuracy the tests ask for. */
#define POSE_ORTHONORMAL_TOL 1e-12

fl_status fl_sweep_pose_check(int dim, const fl_sweep_pose *pose, fl_error *err)
{
    for (int i = 0; i < 9; i++)
        if (!isfinite(pose->r[i]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "pose rotation is not finite");
    for (int i = 0; i < 3; i++)
        if (!fl_sweep_coord_ok(pose->t[i]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "pose translation is not finite or beyond 1e150");
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double dot = 0;
            for (int k = 0; k < 3; k++)
                dot += pose->r[3 * k + i] * pose->r[3 * k + j];
            if (!(fabs(dot - (i == j)) <= POSE_ORTHONORMAL_TOL))
                return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                               "pose rotation is not orthonormal (RᵀR differs from I by %g)",
                               fabs(dot - (i == j)));
        }
    /* A 2D shape lives in z = 0 and must stay there. */
    if (dim == 2 && (pose->r[2] != 0 || pose->r[5] != 0 || pose->r[6] != 0 || pose->r[7] != 0 ||
                     pose->t[2] != 0))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "a 2D pose must keep the plane z = 0 (r[2] = r[5] = r[6] = r[7] = t[2] = 0)");
    return FL_OK;
}

int fl_sweep_pose_to_local(int dim, const fl_sweep_pose *pose, const double *q, double *local)
{
    double w[3];
    for (int c = 0; c < 3; c++) {
        double x = c < dim ? q[c] : 0;
        if (!fl_sweep_coord_ok(x)) return 0;
        w[c] = x - pose->t[c];
    }
    for (int c = 0; c < dim; c++)
        local[c] = pose->r[c] * w[0] + pose->r[3 + c] * w[1] + pose->r[6 + c] * w[2];
    return 1;
}

void fl_sweep_pose_to_world(const fl_sweep_pose *pose, fl_closest *r)
{
    double p[3];
    for (int c = 0; c < 3; c++)
        p[c] = pose->r[3 * c] * r->point[0] + pose->r[3 * c + 1] * r->point[1] +
               pose->r[3 * c + 2] * r->point[2] + pose->t[c];
    for (int c = 0; c < 3; c++)
        r->point[c] = p[c];
}

fl_status fl_sweep_cursor_closest_posed(fl_sweep_cursor *cursor, const fl_sweep_pose *pose,
                                        const double *q, double tolerance, fl_closest *result,
                                        fl_error *err)
{
    if (!cursor || !pose || !q || !result)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "cursor, pose, query and result must not be NULL");
    const fl_sweep *sweep = fl_sweep_cursor_sweep(cursor);
    fl_status st = fl_sweep_pose_check(sweep->dim, pose, err);
    if (st != FL_OK) return st;
    double local[3];
    if (!fl_sweep_pose_to_local(sweep->dim, pose, q, local))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "query point is not finite or beyond 1e150");
    st = fl_sweep_cursor_closest(cursor, local, tolerance, result, err);
    if (st == FL_OK) fl_sweep_pose_to_world(pose, result);
    return st;
}

fl_status fl_sweep_closest_posed(const fl_sweep *sweep, const fl_sweep_pose *pose, const double *q,
                                 size_t nq, double tolerance, fl_closest *results, fl_error *err)
{
    if (nq == 0) return FL_OK;
    if (!sweep || !pose || !q || !results)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "sweep, pose, queries and results must not be NULL");
    fl_sweep_cursor *cur;
    fl_status st = fl_sweep_cursor_new(sweep, &cur, err);
    for (size_t i = 0; i < nq && st == FL_OK; i++)
        st = fl_sweep_cursor_closest_posed(cur, pose, q + i * (size_t)sweep->dim, tolerance,
                                           results + i, err);
    fl_sweep_cursor_free(cur);
    return st;
}

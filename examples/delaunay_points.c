/* Example: read a point file, triangulate it, check the result, print a summary.
 *
 *   cc examples/delaunay_points.c -Iinclude build/libflintstone.a -lm -o delaunay_points
 *   ./delaunay_points data/demo/peanut.xyz
 */
#include <stdio.h>

#include "flintstone.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s POINTS (.xyz .xy .csv .ply .off .obj)\n", argv[0]);
        return 1;
    }
    fl_error err;
    fl_points points;
    if (fl_read_points(argv[1], &points, &err) != FL_OK) {
        char msg[1200];
        fl_error_format(&err, msg, sizeof msg);
        fprintf(stderr, "error: %s\n", msg);
        return err.status;
    }
    fl_status st;
    if (points.dim == 2) {
        fl_dt2 dt;
        st = fl_dt2_build(points.coords, points.count, NULL, &dt, &err);
        if (st == FL_OK) st = fl_dt2_verify(points.coords, &dt, &err);
        if (st == FL_OK)
            printf("%zu points -> %zu triangles, %zu on the convex hull\n", dt.unique_count,
                   dt.triangle_count, dt.hull_count);
        fl_dt2_free(&dt);
    } else {
        fl_dt3 dt;
        st = fl_dt3_build(points.coords, points.count, NULL, &dt, &err);
        if (st == FL_OK) st = fl_dt3_verify(points.coords, &dt, &err);
        if (st == FL_OK)
            printf("%zu points -> %zu tetrahedra, %zu hull triangles\n", dt.unique_count,
                   dt.tet_count, dt.hull_face_count);
        fl_dt3_free(&dt);
    }
    fl_points_free(&points);
    if (st != FL_OK) {
        char msg[1200];
        fl_error_format(&err, msg, sizeof msg);
        fprintf(stderr, "error: %s\n", msg);
    }
    return st;
}

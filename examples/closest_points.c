/* Example: closest points on a triangle mesh (Meshsweeper, fl_sweep).
 *
 *   closest_points MESH QUERIES   prints "distance x y z triangle" for each query point
 *   closest_points [MESH]         demo (default data/demo/torus.off): 10000 points along a
 *                                 helix around the mesh, answered as one coherent stream
 *
 * MESH is any mesh file (.off .obj .ply .stl), QUERIES a 3D point file. The hierarchy is built
 * once (O(T log T)); a batch of queries runs through one cursor, so queries that move a little
 * at a time are answered much faster (Guéziec 2001, §3.3 and §5.1).
 *
 *   cc closest_points.c $(pkg-config --cflags --libs flintstone) -o closest_points
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "flintstone.h"

#ifndef FL_DEMO_DIR
#define FL_DEMO_DIR "data/demo"
#endif

#define DEMO_QUERIES 10000

static int report(const fl_error *err)
{
    char msg[1200];
    fl_error_format(err, msg, sizeof msg);
    fprintf(stderr, "error: %s\n", msg);
    return (int)err->status;
}

/* A helix through the mesh's bounding box: a path of nearby queries, as a probe would move. */
static double *helix_queries(const fl_mesh *mesh, size_t n)
{
    double lo[3], hi[3];
    for (int c = 0; c < 3; c++) lo[c] = hi[c] = mesh->xyz[c];
    for (size_t i = 0; i < mesh->vertex_count; i++)
        for (int c = 0; c < 3; c++) {
            double v = mesh->xyz[3 * i + c];
            lo[c] = v < lo[c] ? v : lo[c];
            hi[c] = v > hi[c] ? v : hi[c];
        }
    double *q = malloc(3 * n * sizeof *q);
    if (!q) return NULL;
    for (size_t k = 0; k < n; k++) {
        double t = (double)k / (double)n, a = 40.0 * 3.141592653589793 * t;
        q[3 * k] = 0.5 * (lo[0] + hi[0]) + 0.6 * (hi[0] - lo[0]) * cos(a);
        q[3 * k + 1] = 0.5 * (lo[1] + hi[1]) + 0.6 * (hi[1] - lo[1]) * sin(a);
        q[3 * k + 2] = lo[2] - 0.2 * (hi[2] - lo[2]) + 1.4 * (hi[2] - lo[2]) * t;
    }
    return q;
}

int main(int argc, char **argv)
{
    if (argc > 3 || (argc > 1 && argv[1][0] == '-')) {
        fprintf(stderr, "usage: %s [MESH [QUERIES]]\n", argv[0]);
        return 1;
    }
    const char *mesh_path = argc > 1 ? argv[1] : FL_DEMO_DIR "/torus.off";
    fl_error err;
    fl_mesh mesh;
    if (fl_read_mesh(mesh_path, &mesh, &err) != FL_OK) return report(&err);
    fl_sweep *sweep = NULL;
    fl_points pts = {0, 3, NULL};
    double *q = NULL;
    size_t n = DEMO_QUERIES;
    fl_closest *res = NULL;
    fl_status st = fl_sweep_build(&mesh, NULL, &sweep, &err);
    if (st == FL_OK && argc > 2) {
        st = fl_read_points(argv[2], &pts, &err);
        if (st == FL_OK && pts.dim != 3) {
            st = err.status = FL_ERR_INPUT;
            snprintf(err.message, sizeof err.message, "%s: need 3D query points", argv[2]);
            err.file[0] = '\0';
        }
        q = pts.coords;
        n = pts.count;
    } else if (st == FL_OK) {
        q = helix_queries(&mesh, n);
    }
    if (st == FL_OK) {
        res = malloc((n ? n : 1) * sizeof *res);
        if (!q || !res) {
            fprintf(stderr, "error: out of memory\n");
            st = FL_ERR_NOMEM;
        }
    }
    if (st == FL_OK) st = fl_sweep_closest(sweep, q, n, 0.0, res, &err);
    if (st == FL_OK && argc > 2) {
        for (size_t k = 0; k < n; k++)
            printf("%.17g %.17g %.17g %.17g %u\n", res[k].distance, res[k].point[0],
                   res[k].point[1], res[k].point[2], (unsigned)res[k].element);
    } else if (st == FL_OK) {
        double sum = 0, max = 0;
        size_t visited = 0, reused = 0;
        for (size_t k = 0; k < n; k++) {
            sum += res[k].distance;
            max = res[k].distance > max ? res[k].distance : max;
            visited += res[k].visited;
            reused += (size_t)res[k].reused;
        }
        printf("%s: %zu triangles; %zu helix queries: mean distance %.6f, max %.6f\n", mesh_path,
               mesh.triangle_count, n, sum / (double)n, max);
        printf("%.1f hierarchy nodes visited a query, %zu answered from the coherence ball\n",
               (double)visited / (double)n, reused);
    } else if (st != FL_ERR_NOMEM) {
        report(&err);
    }
    if (argc <= 2) free(q);
    free(res);
    fl_points_free(&pts);
    fl_sweep_free(sweep);
    fl_mesh_free(&mesh);
    return (int)st;
}

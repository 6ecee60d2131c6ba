/* Our side of the skin timing of bench/workloads/skin.sh: fl_skin_mesh of a ball file read
 * once, timed in-process like the CGAL peer (bench/peers/cgal_skin.cpp) times its mesher call.
 *
 *   ours_skin BALLS.xyzw T CELL [OUT.off [GRADE]]   (CELL 0: the default cell; GRADE > 0: the
 *                                                    graded grid, fl_skin_options.grade)
 *   RESULT seconds=<wall> cpu=<process CPU> vertices=<V> faces=<F> euler=<chi> cell=<h>
 *
 * The timed region is fl_skin_mesh with its stats (regular triangulation, mixed-complex index,
 * marching, and the vertex-offset check of every vertex); reading the balls, the topology
 * report and writing the mesh are outside it. Single-threaded, so CPU time hides nothing. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "flintstone.h"

static double clock_seconds(clockid_t clock)
{
    struct timespec ts;
    clock_gettime(clock, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: ours_skin BALLS.xyzw T CELL [OUT.off [GRADE]]\n");
        return 1;
    }
    fl_error err;
    fl_balls balls = {0};
    if (fl_read_balls(argv[1], &balls, &err) != FL_OK) {
        fprintf(stderr, "ours_skin: %s\n", err.message);
        return 1;
    }
    fl_skin_options opt = {0};
    opt.t = atof(argv[2]);
    opt.cell = atof(argv[3]);
    if (argc > 5) opt.grade = atof(argv[5]);
    fl_mesh mesh = {0};
    fl_skin_stats stats;
    double w0 = clock_seconds(CLOCK_MONOTONIC), c0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
    fl_status st = fl_skin_mesh(balls.xyzw, balls.count, &opt, &mesh, &stats, &err);
    double c1 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID), w1 = clock_seconds(CLOCK_MONOTONIC);
    fl_mesh_report rep = {0};
    fl_mesh_check_options copt = {0};
    copt.skip_self_intersections = 1;
    if (st == FL_OK) st = fl_mesh_check(&mesh, &copt, &rep, &err);
    if (st == FL_OK && argc > 4) st = fl_write_mesh(argv[4], &mesh, &err);
    if (st != FL_OK) {
        fprintf(stderr, "ours_skin: %s\n", err.message);
        return 1;
    }
    printf("RESULT seconds=%.6f cpu=%.6f vertices=%zu faces=%zu euler=%lld cell=%.9g\n", w1 - w0,
           c1 - c0, mesh.vertex_count, mesh.triangle_count, (long long)rep.euler, stats.cell);
    fl_mesh_report_free(&rep);
    fl_mesh_free(&mesh);
    fl_balls_free(&balls);
    return 0;
}

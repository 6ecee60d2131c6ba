/* Our side of the skin timing of bench/workloads/skin.sh: fl_skin_mesh of a ball file read
 * once, timed in-process like the CGAL peer (bench/peers/cgal_skin.cpp) times its mesher call.
 *
 *   ours_skin BALLS.xyzw T CELL [OUT.off [GRADE]]   (CELL 0 and GRADE 0: the default of
 *                                                    `skin --balls`, fl_skin_mesh_checked;
 *                                                    CELL > 0: that uniform cell, -1 the
 *                                                    uniform default cell; GRADE > 0:
 *                                                    the graded grid, fl_skin_options.grade)
 *   RESULT seconds=<wall> cpu=<process CPU> vertices=<V> faces=<F> euler=<chi> cell=<h>
 *          expected=<2 chi(union)> attempts=<meshes> grade=<of the mesh kept> check_cpu=<s>
 *
 * The timed region is the mesher with its stats (regular triangulation, mixed-complex index,
 * marching, and the vertex-offset check of every vertex): fl_skin_mesh_checked for the default
 * (so it includes the exact Euler characteristic of the union, fl_balls_union_euler, and every
 * retry), fl_skin_mesh otherwise. check_cpu is fl_balls_union_euler alone, timed after. Reading
 * the balls, the topology report and writing the mesh are outside it. Single-threaded, so CPU
 * time hides nothing. */
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
    fl_skin_check check = {0};
    int checked = opt.cell == 0 && opt.grade == 0;
    if (opt.cell < 0) opt.cell = 0; /* CELL -1: the uniform grid's default cell, unchecked */
    double w0 = clock_seconds(CLOCK_MONOTONIC), c0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
    fl_status st =
        checked ? fl_skin_mesh_checked(balls.xyzw, balls.count, &opt, &mesh, &stats, &check, &err)
                : fl_skin_mesh(balls.xyzw, balls.count, &opt, &mesh, &stats, &err);
    double c1 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID), w1 = clock_seconds(CLOCK_MONOTONIC);
    long long chi = 0;
    if (st == FL_OK) st = fl_balls_union_euler(balls.xyzw, balls.count, &chi, &err);
    double c2 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
    if (!checked) {
        check.attempts = 1;
        check.grade = opt.grade;
    }
    fl_mesh_report rep = {0};
    fl_mesh_check_options copt = {0};
    copt.skip_self_intersections = 1;
    if (st == FL_OK) st = fl_mesh_check(&mesh, &copt, &rep, &err);
    if (st == FL_OK && argc > 4) st = fl_write_mesh(argv[4], &mesh, &err);
    if (st != FL_OK) {
        fprintf(stderr, "ours_skin: %s\n", err.message);
        return 1;
    }
    printf("RESULT seconds=%.6f cpu=%.6f vertices=%zu faces=%zu euler=%lld cell=%.9g "
           "expected=%lld attempts=%d grade=%g check_cpu=%.6f\n",
           w1 - w0, c1 - c0, mesh.vertex_count, mesh.triangle_count, (long long)rep.euler,
           stats.cell, 2 * chi, check.attempts, check.grade, c2 - c1);
    fl_mesh_report_free(&rep);
    fl_mesh_free(&mesh);
    fl_balls_free(&balls);
    return 0;
}

/* Our side of the self-intersection timing of bench/workloads/check_mesh.sh: fl_mesh_check
 * with and without the self-intersection search on a mesh read once, so that the difference
 * is the search alone (box tree + exact pair tests), in-process, without the reader.
 *
 *   ours_check FILE REPS
 *   SI wall_full_s=<s> wall_skip_s=<s> cpu_full_s=<s> cpu_skip_s=<s> pairs=<n>
 *
 * One untimed warm-up of each, then REPS runs of each, alternating; medians, wall clock and
 * process CPU time (single-threaded, so CPU time hides no parallelism). */
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

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, compare_doubles);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* One fl_mesh_check; adds its wall and CPU seconds at *wall, *cpu; returns the pair count. */
static long run_check(const fl_mesh *mesh, int skip, double *wall, double *cpu)
{
    fl_mesh_check_options opt = {skip, NULL, NULL};
    fl_mesh_report r;
    fl_error err;
    double w0 = clock_seconds(CLOCK_MONOTONIC), c0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
    if (fl_mesh_check(mesh, &opt, &r, &err) != FL_OK) {
        fprintf(stderr, "ours_check: %s\n", err.message);
        return -1;
    }
    *wall = clock_seconds(CLOCK_MONOTONIC) - w0;
    *cpu = clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - c0;
    long pairs = (long)r.self_intersections;
    fl_mesh_report_free(&r);
    return pairs;
}

int main(int argc, char **argv)
{
    int reps = argc == 3 ? atoi(argv[2]) : 0;
    if (reps < 1 || reps > 100) {
        fprintf(stderr, "usage: ours_check FILE REPS (1..100)\n");
        return 2;
    }
    fl_mesh mesh;
    fl_error err;
    if (fl_read_mesh(argv[1], &mesh, &err) != FL_OK) {
        fprintf(stderr, "ours_check: %s\n", err.message);
        return 1;
    }
    double wf[100], ws[100], cf[100], cs[100], w, c;
    long pairs = run_check(&mesh, 0, &w, &c);
    int ok = pairs >= 0 && run_check(&mesh, 1, &w, &c) >= 0;
    for (int i = 0; ok && i < reps; i++)
        ok = run_check(&mesh, 1, &ws[i], &cs[i]) >= 0 && run_check(&mesh, 0, &wf[i], &cf[i]) >= 0;
    fl_mesh_free(&mesh);
    if (!ok) return 1;
    printf("SI wall_full_s=%.6f wall_skip_s=%.6f cpu_full_s=%.6f cpu_skip_s=%.6f pairs=%ld\n",
           median(wf, reps), median(ws, reps), median(cf, reps), median(cs, reps), pairs);
    return 0;
}

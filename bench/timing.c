/* Timing protocol shared by every reader benchmark; see timing.h. */
#define _POSIX_C_SOURCE 200809L
#include "timing.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#define BENCH_MAX_REPS 100

static double clock_seconds(clockid_t clock)
{
    struct timespec ts;
    clock_gettime(clock, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Reads the whole file once so that every timed run of every reader finds it in the page
 * cache: the benchmark measures parsing, not the disk. */
static int warm_page_cache(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) {
        fprintf(stderr, "cannot open %s\n", path);
        return 1;
    }
    static char buf[1 << 16];
    while (fread(buf, 1, sizeof buf, fp) == sizeof buf) {
    }
    fclose(fp);
    return 0;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sorts the n values and returns their median (the mean of the middle two for even n). */
static double median(double *values, int n)
{
    qsort(values, (size_t)n, sizeof values[0], compare_doubles);
    return (values[(n - 1) / 2] + values[n / 2]) / 2;
}

/* Wall time is what a user waits for; the CPU time of the process leaves out time spent waiting
 * for a core, which on a shared machine makes it the steadier of the two. */
static int run_once(const bench_reader *r, const char *path, double *wall, double *cpu, size_t *v,
                    size_t *t)
{
    void *result = NULL;
    double wall0 = clock_seconds(CLOCK_MONOTONIC);
    double cpu0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
    int failed = r->load(r->ctx, path, &result, v, t);
    *cpu = clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
    *wall = clock_seconds(CLOCK_MONOTONIC) - wall0;
    if (result) r->release(r->ctx, result);
    return failed;
}

int bench_time_reader(const bench_reader *r, const char *path, int reps)
{
    double wall[BENCH_MAX_REPS], cpu[BENCH_MAX_REPS];
    size_t v = 0, t = 0;
    if (reps < 1 || reps > BENCH_MAX_REPS) return 1;
    if (warm_page_cache(path) || run_once(r, path, &wall[0], &cpu[0], &v, &t)) return 1;
    for (int i = 0; i < reps; i++) {
        size_t vi, ti;
        if (run_once(r, path, &wall[i], &cpu[i], &vi, &ti)) return 1;
        if (vi != v || ti != t) {
            fprintf(stderr, "%s: counts changed between runs\n", r->name);
            return 1;
        }
    }
    double wall_median = median(wall, reps), cpu_median = median(cpu, reps);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("RESULT reader=%s file=%s reps=%d median_s=%.6f min_s=%.6f max_s=%.6f "
           "cpu_median_s=%.6f vertices=%zu triangles=%zu maxrss_kb=%ld\n",
           r->name, path, reps, wall_median, wall[0], wall[reps - 1], cpu_median, v, t,
           ru.ru_maxrss);
    return 0;
}

int bench_parse_args(int argc, char **argv, const char **path, int *reps)
{
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: %s FILE [REPS]\n", argv[0]);
        return 1;
    }
    *path = argv[1];
    *reps = 5;
    if (argc == 3) {
        char *end;
        long n = strtol(argv[2], &end, 10);
        if (*end || n < 1 || n > BENCH_MAX_REPS) {
            fprintf(stderr, "%s: REPS must be 1..%d\n", argv[0], BENCH_MAX_REPS);
            return 1;
        }
        *reps = (int)n;
    }
    return 0;
}

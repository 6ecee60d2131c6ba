/* Timing protocol shared by every reader benchmark; see timing.h. */
#define _POSIX_C_SOURCE 200809L
#include "timing.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#define BENCH_MAX_REPS 100

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
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

static int run_once(const bench_reader *r, const char *path, double *seconds, size_t *v, size_t *t)
{
    void *result = NULL;
    double start = now_seconds();
    int failed = r->load(r->ctx, path, &result, v, t);
    double stop = now_seconds();
    if (result) r->release(r->ctx, result);
    *seconds = stop - start;
    return failed;
}

int bench_time_reader(const bench_reader *r, const char *path, int reps)
{
    double times[BENCH_MAX_REPS];
    size_t v = 0, t = 0;
    double warmup;
    if (reps < 1 || reps > BENCH_MAX_REPS) return 1;
    if (warm_page_cache(path) || run_once(r, path, &warmup, &v, &t)) return 1;
    for (int i = 0; i < reps; i++) {
        size_t vi, ti;
        if (run_once(r, path, &times[i], &vi, &ti)) return 1;
        if (vi != v || ti != t) {
            fprintf(stderr, "%s: counts changed between runs\n", r->name);
            return 1;
        }
    }
    qsort(times, (size_t)reps, sizeof times[0], compare_doubles);
    /* For an even count the median is the mean of the two middle runs. */
    double median = (times[(reps - 1) / 2] + times[reps / 2]) / 2;
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("RESULT reader=%s file=%s reps=%d median_s=%.6f min_s=%.6f max_s=%.6f vertices=%zu "
           "triangles=%zu maxrss_kb=%ld\n",
           r->name, path, reps, median, times[0], times[reps - 1], v, t, ru.ru_maxrss);
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

/* Shared timing harness of the bench programs (ours_read.c, peers/assimp_read.c, ...).
 *
 * Every reader benchmark times the same thing the same way: the file is first read once into
 * /dev/null so it sits in the page cache, then the reader runs once untimed (warm-up: first-touch
 * page faults of the allocator, lazy symbol binding, caches), then `reps` timed runs. Freeing the
 * result is outside the timed region for every reader. The program prints one machine-readable
 * line that the scripts in bench/workloads/ parse:
 *
 *   RESULT reader=<name> file=<path> reps=<n> median_s=<s> min_s=<s> max_s=<s>
 *          cpu_median_s=<s> vertices=<n> triangles=<n> maxrss_kb=<kb>
 *
 * median/min/max are wall-clock seconds; cpu_median_s is the median CPU time of the process.
 */
#ifndef FL_BENCH_TIMING_H
#define FL_BENCH_TIMING_H

#include <stddef.h>

/* One run of a reader on `path`. Returns 0 on success and fills the counts of what it built;
 * on failure prints why to stderr and returns nonzero. `result` receives whatever the reader
 * must free afterwards; `release` frees it (called outside the timed region). */
typedef struct bench_reader {
    const char *name;
    int (*load)(void *ctx, const char *path, void **result, size_t *vertices, size_t *triangles);
    void (*release)(void *ctx, void *result);
    void *ctx;
} bench_reader;

/* Runs the protocol above and prints the RESULT line. Returns 0 on success. */
int bench_time_reader(const bench_reader *reader, const char *path, int reps);

/* Parses "<prog> FILE [REPS]" (REPS defaults to 5, at most 100). Returns 0 on success. */
int bench_parse_args(int argc, char **argv, const char **path, int *reps);

#endif /* FL_BENCH_TIMING_H */

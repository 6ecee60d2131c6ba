/* Our side of the Delaunay benchmarks: fl_dt2_build, fl_dt3_build or fl_rt3_build on points
 * already in memory, timed with the protocol of bench/timing.h (one warm-up build, median of
 * REPS builds, freeing outside the timing).
 *
 *   ours_delaunay [--verify] dt2|dt3|rt3 FILE.bin [REPS]
 *
 * FILE.bin comes from bench/gen_points.c (2, 3 or 4 doubles a point for dt2, dt3, rt3) and is
 * read before any timing. The RESULT line's `vertices` is the number of vertices of the
 * triangulation (distinct points; for rt3 without the hidden balls), `triangles` the number of
 * triangles (dt2) or tetrahedra (dt3, rt3). --verify checks one more build with fl_dt*_verify /
 * fl_rt3_verify (exact predicates, outside the timing) and prints "VERIFY ok" or why not. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "flintstone.h"
#include "pointfile.h"
#include "timing.h"

typedef struct input {
    int dim; /* 2: dt2, 3: dt3, 4: rt3 */
    double *coords;
    size_t n;
} input;

typedef union built {
    fl_dt2 dt2;
    fl_dt3 dt3;
    fl_rt3 rt3;
} built;

static int report(fl_status status, const fl_error *err)
{
    if (status == FL_OK) return 0;
    char msg[1200];
    fl_error_format(err, msg, sizeof msg);
    fprintf(stderr, "ours: %s\n", msg);
    return 1;
}

static int build(void *ctx, const char *path, void **result, size_t *vertices, size_t *cells)
{
    (void)path; /* the points are in memory already */
    const input *in = ctx;
    built *b = calloc(1, sizeof *b);
    fl_error err;
    fl_status status;
    if (!b) return 1;
    if (in->dim == 2) {
        status = fl_dt2_build(in->coords, in->n, NULL, &b->dt2, &err);
        *vertices = b->dt2.unique_count;
        *cells = b->dt2.triangle_count;
    } else if (in->dim == 3) {
        status = fl_dt3_build(in->coords, in->n, NULL, &b->dt3, &err);
        *vertices = b->dt3.unique_count;
        *cells = b->dt3.tet_count;
    } else {
        status = fl_rt3_build(in->coords, in->n, NULL, &b->rt3, &err);
        *vertices = b->rt3.vertex_count;
        *cells = b->rt3.tet_count;
    }
    if (report(status, &err)) {
        free(b);
        return 1;
    }
    *result = b;
    return 0;
}

static void release(void *ctx, void *result)
{
    const input *in = ctx;
    built *b = result;
    if (in->dim == 2) fl_dt2_free(&b->dt2);
    if (in->dim == 3) fl_dt3_free(&b->dt3);
    if (in->dim == 4) fl_rt3_free(&b->rt3);
    free(b);
}

static int verify(input *in, const char *path)
{
    void *result = NULL;
    size_t v, c;
    if (build(in, path, &result, &v, &c)) return 1;
    built *b = result;
    fl_error err;
    fl_status status = in->dim == 2   ? fl_dt2_verify(in->coords, &b->dt2, &err)
                       : in->dim == 3 ? fl_dt3_verify(in->coords, &b->dt3, &err)
                                      : fl_rt3_verify(in->coords, &b->rt3, &err);
    release(in, result);
    if (report(status, &err)) return 1;
    printf("VERIFY ok vertices=%zu cells=%zu\n", v, c);
    return 0;
}

int main(int argc, char **argv)
{
    int check = argc > 1 && !strcmp(argv[1], "--verify");
    argc -= check;
    argv += check;
    if (argc < 3) {
        fprintf(stderr, "usage: ours_delaunay [--verify] dt2|dt3|rt3 FILE.bin [REPS]\n");
        return 2;
    }
    input in = {!strcmp(argv[1], "dt2") ? 2 : !strcmp(argv[1], "dt3") ? 3 : 4, NULL, 0};
    if (in.dim == 4 && strcmp(argv[1], "rt3")) {
        fprintf(stderr, "ours_delaunay: unknown mode %s\n", argv[1]);
        return 2;
    }
    const char *path;
    int reps;
    if (bench_parse_args(argc - 1, argv + 1, &path, &reps)) return 2;
    if (!(in.coords = bench_read_points(path, in.dim, &in.n))) return 1;
    const char *names[] = {"ours_dt2", "ours_dt3", "ours_rt3"};
    bench_reader reader = {names[in.dim - 2], build, release, &in};
    int failed = check ? verify(&in, path) : bench_time_reader(&reader, path, reps);
    free(in.coords);
    return failed ? 1 : 0;
}

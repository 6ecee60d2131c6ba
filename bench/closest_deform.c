/* Ours in the deforming-mesh closest-point benchmark (bench/deform_eval.h; docs/sweep.md,
 * "Deforming mesh against CGAL"; bench/workloads/closest_deform.sh):
 *   closest_deform PREFIX MODE [FRAMES [QUERIES]]     (defaults 20 frames, 10 000 queries a frame)
 * MODE update:  fl_sweep_build on frame 0, then fl_sweep_update_vertices every later frame
 *               (Guéziec §5.2: the hierarchy is kept, its volumes refitted bottom-up); one
 *               fl_sweep_cursor for the whole run, so the walk's kept queue crosses frames.
 * MODE rebuild: fl_sweep_build every frame and a fresh cursor on it.
 * MODE collapse_update: the edge-collapse hierarchy (§4.2-4.3): fl_sweep_collapse_build on
 *               frame 0, then fl_sweep_collapse_update_vertices every later frame (§5.3's
 *               displacement inflation); one fl_sweep_collapse_cursor for the whole run.
 * MODE collapse_refit: as collapse_update plus fl_sweep_collapse_refit after every update.
 * MODE collapse_rebuild: fl_sweep_collapse_build every frame and a fresh cursor on it.
 * MODE brute:   every triangle for the first min(200, QUERIES) queries of frame 0 only.
 * Times (wall and process CPU) cover the build/update and the queries, not the making of the
 * frame's vertices or queries (the same for every method). Writes the distances, one double a
 * query in order, to PREFIX.deform.MODE.d; prints one FRAME line a frame and a RESULT line. */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "deform_eval.h"
#include "flintstone.h"

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct clocks {
    double wall, cpu;
} clocks;

static clocks clocks_now(void)
{
    clocks c = {ce_now(), cpu_now()};
    return c;
}

static void clocks_add(clocks *sum, clocks since)
{
    clocks now = clocks_now();
    sum->wall += now.wall - since.wall;
    sum->cpu += now.cpu - since.cpu;
}

/* Frame 0's first n queries against every triangle. */
static double brute(const ce_mesh *m, const double *xyz, const double *q, size_t n, double *d)
{
    double sum = 0;
    for (size_t i = 0; i < n; i++) {
        double best = INFINITY;
        for (uint64_t t = 0; t < m->t; t++) {
            const uint32_t *v = m->tri + 3 * t;
            double e = de_point_triangle2(q + 3 * i, xyz + 3 * v[0], xyz + 3 * v[1], xyz + 3 * v[2]);
            best = e < best ? e : best;
        }
        d[i] = sqrt(best);
        sum += d[i];
    }
    return sum;
}

/* Moves the hierarchy to frame `xyz`: a build on the first frame or in rebuild mode, else an
 * update. Returns 0 on success. */
static int move(int rebuild, const ce_mesh *m, double *xyz, fl_sweep **sweep,
                fl_sweep_cursor **cursor)
{
    fl_error err;
    fl_status st;
    if (*sweep && !rebuild) {
        st = fl_sweep_update_vertices(*sweep, xyz, &err);
    } else {
        fl_sweep_cursor_free(*cursor);
        fl_sweep_free(*sweep);
        *cursor = NULL;
        fl_mesh fm = {(size_t)m->v, xyz, (size_t)m->t, m->tri};
        st = fl_sweep_build(&fm, NULL, sweep, &err);
        if (st == FL_OK) st = fl_sweep_cursor_new(*sweep, cursor, &err);
    }
    if (st != FL_OK) fprintf(stderr, "closest_deform: %s\n", err.message);
    return st != FL_OK;
}

/* The edge-collapse hierarchy's counterpart of move(): refit 1 adds a refit to each update. */
static int move_collapse(int rebuild, int refit, const ce_mesh *m, double *xyz,
                         fl_sweep_collapse **h, fl_sweep_collapse_cursor **cursor)
{
    fl_error err;
    fl_status st;
    if (*h && !rebuild) {
        st = fl_sweep_collapse_update_vertices(*h, xyz, (size_t)m->v, &err);
        if (st == FL_OK && refit) st = fl_sweep_collapse_refit(*h, &err);
    } else {
        fl_sweep_collapse_cursor_free(*cursor);
        fl_sweep_collapse_free(*h);
        *cursor = NULL;
        fl_mesh fm = {(size_t)m->v, xyz, (size_t)m->t, m->tri};
        st = fl_sweep_collapse_build(&fm, NULL, h, &err);
        if (st == FL_OK) st = fl_sweep_collapse_cursor_new(*h, cursor, &err);
    }
    if (st != FL_OK) fprintf(stderr, "closest_deform: %s\n", err.message);
    return st != FL_OK;
}

int main(int argc, char **argv)
{
    static const char *modes[] = {"update", "rebuild", "brute", "collapse_update",
                                  "collapse_refit", "collapse_rebuild"};
    int mode = -1;
    for (int i = 0; argc >= 3 && i < 6; i++)
        if (strcmp(argv[2], modes[i]) == 0) mode = i;
    if (mode < 0) {
        fprintf(stderr, "usage: closest_deform PREFIX update|rebuild|brute|collapse_update|"
                        "collapse_refit|collapse_rebuild [FRAMES [QUERIES]]\n");
        return 2;
    }
    int collapse = mode >= 3;
    (void)ce_read_queries; /* closest_eval.h's query files: the queries here are made per frame */
    int frames = argc > 3 ? atoi(argv[3]) : 20;
    long nq = argc > 4 ? atol(argv[4]) : 10000;
    int rebuild = mode == 1 || mode == 5, is_brute = mode == 2;
    ce_mesh m;
    if (frames < 1 || nq < 1 || ce_read_mesh(argv[1], &m)) {
        fprintf(stderr, "closest_deform: bad arguments or unreadable %s.mesh\n", argv[1]);
        return 1;
    }
    de_setup s;
    de_init(&s, &m);
    if (is_brute) frames = 1;
    size_t per_frame = is_brute && nq > 200 ? 200 : (size_t)nq;
    double *xyz = malloc(m.v * 3 * sizeof(double));
    double *q = malloc((size_t)nq * 3 * sizeof(double));
    double *d = malloc((size_t)frames * per_frame * sizeof(double));
    if (!xyz || !q || !d) return 1;
    fl_sweep *sweep = NULL;
    fl_sweep_cursor *cursor = NULL;
    fl_sweep_collapse *ch = NULL;
    fl_sweep_collapse_cursor *ccursor = NULL;
    size_t visited = 0;
    clocks moved = {0, 0}, queried = {0, 0};
    double checksum = 0, build0 = 0;
    int failed = 0;
    for (int f = 0; f < frames && !failed; f++) {
        de_frame(&s, &m, f, frames, xyz);
        de_walk(&s, q, (uint64_t)nq);
        clocks m0 = moved, q0 = queried, t = clocks_now();
        double sum = 0, *df = d + (size_t)f * per_frame;
        if (is_brute) {
            sum = brute(&m, xyz, q, per_frame, df);
            clocks_add(&queried, t);
        } else {
            failed = collapse ? move_collapse(rebuild, mode == 4, &m, xyz, &ch, &ccursor)
                              : move(rebuild, &m, xyz, &sweep, &cursor);
            clocks_add(&moved, t);
            if (f == 0) build0 = moved.wall;
            t = clocks_now();
            for (size_t i = 0; i < per_frame && !failed; i++) {
                fl_closest r;
                fl_error err;
                failed = (collapse ? fl_sweep_collapse_cursor_closest(ccursor, q + 3 * i, 0, &r, &err)
                                   : fl_sweep_cursor_closest(cursor, q + 3 * i, 0, &r, &err)) !=
                         FL_OK;
                df[i] = r.distance;
                sum += r.distance;
                visited += r.visited;
            }
            clocks_add(&queried, t);
        }
        checksum += sum;
        printf("FRAME f=%d move_s=%.6f query_s=%.6f move_cpu_s=%.6f query_cpu_s=%.6f "
               "checksum=%.17g\n",
               f, moved.wall - m0.wall, queried.wall - q0.wall, moved.cpu - m0.cpu,
               queried.cpu - q0.cpu, sum);
    }
    fl_sweep_cursor_free(cursor);
    fl_sweep_free(sweep);
    fl_sweep_collapse_cursor_free(ccursor);
    fl_sweep_collapse_free(ch);
    if (!failed) {
        ce_write_distances(argv[1], "deform", argv[2], d, (size_t)frames * per_frame);
        double total = moved.wall + queried.wall, n = (double)frames * (double)per_frame;
        printf("RESULT method=ours-%s frames=%d queries=%zu build0_s=%.6f move_s=%.6f "
               "query_s=%.6f total_s=%.6f cpu_s=%.6f move_cpu_s=%.6f qps=%.1f visited=%zu "
               "checksum=%.17g\n",
               argv[2], frames, per_frame, build0, moved.wall, queried.wall, total,
               moved.cpu + queried.cpu, moved.cpu, n / total, visited, checksum);
    }
    free(xyz);
    free(q);
    free(d);
    free(m.xyz);
    free(m.tri);
    return failed;
}

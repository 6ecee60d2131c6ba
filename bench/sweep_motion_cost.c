/* Cost of keeping a deforming mesh queryable (docs/sweep.md "Moving shapes"): per time step,
 * key-frame interpolation (fl_sweep_keyframes_set_time), the bottom-up update
 * (fl_sweep_update_vertices) and a rebuild (fl_sweep_build), each followed by the same random
 * queries near the mesh. A noisy torus with `nu * nv * 2` triangles deforms through 5 key
 * frames (a wave and a twist growing with the frame); the three methods alternate per round,
 * CPU time (CLOCK_PROCESS_CPUTIME_ID) of the process, median of `rounds` rounds.
 *
 *   cc -O2 -std=c11 -Iinclude bench/sweep_motion_cost.c <release build>/libflintstone.a -lm \
 *      -o /tmp/sweep_motion_cost && /tmp/sweep_motion_cost [nu nv steps queries rounds]
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "flintstone.h"

#define FRAMES 5

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static unsigned long long state = 88172645463325252ULL;

static double uniform(double lo, double hi)
{
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return lo + (hi - lo) * (double)(state >> 11) * (1.0 / 9007199254740992.0);
}

static fl_mesh torus(int nu, int nv)
{
    fl_mesh m = {(size_t)nu * nv, malloc(3 * (size_t)nu * nv * sizeof(double)),
                 2 * (size_t)nu * nv, malloc(6 * (size_t)nu * nv * sizeof(uint32_t))};
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double a = 6.283185307179586 * i / nu, b = 6.283185307179586 * j / nv;
            double r = 0.35 * (1 + uniform(-0.05, 0.05)), *p = m.xyz + 3 * ((size_t)i * nv + j);
            p[0] = (1 + r * cos(b)) * cos(a), p[1] = (1 + r * cos(b)) * sin(a), p[2] = r * sin(b);
            uint32_t v00 = (uint32_t)(i * nv + j), v10 = (uint32_t)(((i + 1) % nu) * nv + j);
            uint32_t v11 = (uint32_t)(((i + 1) % nu) * nv + (j + 1) % nv);
            uint32_t v01 = (uint32_t)(i * nv + (j + 1) % nv);
            uint32_t q[6] = {v00, v10, v11, v00, v11, v01};
            memcpy(m.tri + 6 * ((size_t)i * nv + j), q, sizeof q);
        }
    return m;
}

static void frame(const double *rest, double *out, size_t nv, int f)
{
    for (size_t v = 0; v < nv; v++) {
        const double *p = rest + 3 * v;
        double a = 0.6 * f * p[2], ca = cos(a), sa = sin(a);
        out[3 * v] = ca * p[0] - sa * p[1];
        out[3 * v + 1] = sa * p[0] + ca * p[1];
        out[3 * v + 2] = p[2] + 0.1 * f * sin(3 * p[0]);
    }
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

typedef struct tally {
    double prepare, move, query;
    size_t visited;
} tally;

/* One round of one method: 0 key frames, 1 update, 2 rebuild. */
static void run(int method, const fl_mesh *m, const double *frames, int steps, const double *q,
                size_t nq, tally *t)
{
    fl_error err;
    fl_closest *r = malloc(nq * sizeof *r);
    double *now = malloc(3 * m->vertex_count * sizeof *now);
    fl_mesh cur = {m->vertex_count, now, m->triangle_count, m->tri};
    fl_sweep_keyframes *kf = NULL;
    fl_sweep *s = NULL;
    double t0 = cpu_now();
    if (method == 0) fl_sweep_keyframes_new(m, frames, FRAMES, NULL, &kf, &err);
    if (method == 1) fl_sweep_build(m, NULL, &s, &err);
    *t = (tally){cpu_now() - t0, 0, 0, 0};
    for (int k = 1; k <= steps; k++) {
        double time = (FRAMES - 1.0) * k / steps;
        size_t f = (size_t)time < FRAMES - 1 ? (size_t)time : FRAMES - 2;
        double x = time - (double)f, *a = (double *)frames + 3 * m->vertex_count * f;
        for (size_t i = 0; i < 3 * m->vertex_count; i++)
            now[i] = (1 - x) * a[i] + x * a[i + 3 * m->vertex_count];
        const fl_sweep *use;
        t0 = cpu_now();
        if (method == 0) {
            fl_sweep_keyframes_set_time(kf, time, &err);
            use = fl_sweep_keyframes_sweep(kf);
        } else if (method == 1) {
            fl_sweep_update_vertices(s, now, &err);
            use = s;
        } else {
            fl_sweep_free(s);
            fl_sweep_build(&cur, NULL, &s, &err);
            use = s;
        }
        double t1 = cpu_now();
        fl_sweep_closest(use, q, nq, 0, r, &err);
        double t2 = cpu_now();
        t->move += t1 - t0, t->query += t2 - t1;
        for (size_t i = 0; i < nq; i++)
            t->visited += r[i].visited;
    }
    fl_sweep_keyframes_free(kf);
    fl_sweep_free(s);
    free(now);
    free(r);
}

int main(int argc, char **argv)
{
    int nu = argc > 1 ? atoi(argv[1]) : 200, nv = argc > 2 ? atoi(argv[2]) : 100;
    int steps = argc > 3 ? atoi(argv[3]) : 40, rounds = argc > 5 ? atoi(argv[5]) : 3;
    size_t nq = argc > 4 ? (size_t)atol(argv[4]) : 200;
    if (nu < 3 || nv < 3 || steps < 1 || rounds < 1 || rounds > 15 || nq < 1) return 2;
    fl_mesh m = torus(nu, nv);
    double *frames = malloc(FRAMES * 3 * m.vertex_count * sizeof *frames);
    for (int f = 0; f < FRAMES; f++)
        frame(m.xyz, frames + (size_t)f * 3 * m.vertex_count, m.vertex_count, f);
    double *q = malloc(3 * nq * sizeof *q);
    for (size_t i = 0; i < 3 * nq; i++)
        q[i] = uniform(-1.6, 1.6);
    static const char *name[3] = {"keyframes", "update", "rebuild"};
    double move[3][15], query[3][15], prep[3][15];
    size_t visited[3] = {0};
    for (int k = 0; k < rounds; k++)
        for (int method = 0; method < 3; method++) {
            tally t;
            run(method, &m, frames, steps, q, nq, &t);
            move[method][k] = t.move / steps, query[method][k] = t.query / steps;
            prep[method][k] = t.prepare, visited[method] = t.visited / ((size_t)steps * nq);
        }
    printf("triangles=%zu frames=%d steps=%d queries/step=%zu rounds=%d\n", m.triangle_count,
           FRAMES, steps, nq, rounds);
    for (int method = 0; method < 3; method++) {
        qsort(move[method], (size_t)rounds, sizeof(double), cmp);
        qsort(query[method], (size_t)rounds, sizeof(double), cmp);
        qsort(prep[method], (size_t)rounds, sizeof(double), cmp);
        printf("%-10s prepare_s=%.4f step_ms=%.3f queries_ms=%.3f distances/query=%zu\n",
               name[method], prep[method][rounds / 2], 1e3 * move[method][rounds / 2],
               1e3 * query[method][rounds / 2], visited[method]);
    }
    free(q);
    free(frames);
    free(m.xyz);
    free(m.tri);
    return 0;
}

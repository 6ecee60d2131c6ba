/* CPU-time and identity checks for 2D constriction (docs/reconstruct2d.md, "Speed on a closed
 * curve"). Under a shared machine's load wall time says little; this measures the thread's CPU
 * time and its minor page faults around each call, and hashes every output field so that two
 * builds of the library can be compared for identical results.
 *   recon2_cpu time FILE.xy dt|rec K   K calls on the first ring of FILE (shuffled as
 *                                       bench/recon2_eval.h does); prints each CPU time, the
 *                                       least, and the page faults of each call
 *   recon2_cpu hash FILE.xy MIN_POINTS [V]  every ring with at least MIN_POINTS points, the
 *                                       three criteria, then γ with two of the ring's edges kept
 *                                       (only the first V of these four runs when V is given)
 *   recon2_cpu random SEED COUNT        COUNT random sets (uniform or grid-snapped, with
 *                                       duplicates) of 3000-50000 points, as `hash`
 * `hash` and `random` print one line per run "H <case> <variant> <hash>" and a final
 * "TOTAL <runs> <ok> <hash>"; diff the outputs of two builds. Build against a release library:
 *   cc -O2 -Iinclude bench/tools/recon2_cpu.c build-rel/libflintstone.a -lm -o recon2_cpu */
#define _POSIX_C_SOURCE 200809L
#include <sys/resource.h>
#include <time.h>

#include "flintstone.h"
#include "../recon2_eval.h"

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static long minflt(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_minflt;
}

static uint64_t fnv(uint64_t h, const void *p, size_t bytes)
{
    const unsigned char *c = (const unsigned char *)p;
    for (size_t i = 0; i < bytes; i++)
        h = (h ^ c[i]) * 0x100000001b3ull;
    return h;
}

/* Every field of the result, and the status. */
static uint64_t hash_run(const double *xy, size_t n, const fl_reconstruct2_options *opt, int *ok)
{
    fl_reconstruction2 r;
    fl_error err;
    fl_status st = fl_reconstruct2(xy, n, opt, &r, &err);
    uint64_t h = fnv(0xcbf29ce484222325ull, &st, sizeof st);
    *ok = st == FL_OK;
    if (st != FL_OK) return fnv(h, err.message, strlen(err.message));
    h = fnv(h, &r.point_count, sizeof r.point_count);
    h = fnv(h, &r.unique_count, sizeof r.unique_count);
    h = fnv(h, &r.boundary_count, sizeof r.boundary_count);
    h = fnv(h, r.boundary, r.boundary_count * sizeof *r.boundary);
    h = fnv(h, &r.triangle_count, sizeof r.triangle_count);
    h = fnv(h, r.tri, 3 * r.triangle_count * sizeof *r.tri);
    h = fnv(h, &r.delaunay_count, sizeof r.delaunay_count);
    h = fnv(h, r.delaunay_tri, 3 * r.delaunay_count * sizeof *r.delaunay_tri);
    h = fnv(h, &r.all_on_boundary, sizeof r.all_on_boundary);
    h = fnv(h, &r.augmented_c0, sizeof r.augmented_c0);
    h = fnv(h, &r.area, sizeof r.area);
    h = fnv(h, r.reason, strlen(r.reason));
    fl_reconstruction2_free(&r);
    return h;
}

static uint64_t total = 0xcbf29ce484222325ull;
static size_t runs, oks;
static int variants = 4;

/* The three criteria, then γ with two edges kept: keep[] are input indices. */
static void hash_case(size_t k, const double *xy, size_t n, const uint32_t keep[4])
{
    for (int v = 0; v < variants; v++) {
        fl_reconstruct2_options o = {0};
        o.criterion = v < 3 ? (fl_reconstruct2_criterion)v : FL_RECONSTRUCT2_GAMMA;
        if (v == 3) {
            o.keep = keep;
            o.keep_count = 2;
        }
        int ok;
        uint64_t h = hash_run(xy, n, &o, &ok);
        printf("H %zu %d %016llx\n", k, v, (unsigned long long)h);
        total = fnv(total, &h, sizeof h);
        runs++;
        oks += (size_t)ok;
    }
}

static int cmd_time(const r2_set *s, const char *mode, int reps)
{
    const r2_case *c = &s->cases[0];
    int rec = strcmp(mode, "rec") == 0;
    double least = INFINITY;
    printf("CPU mode=%s n=%zu", mode, c->n);
    for (int r = 0; r < reps; r++) {
        fl_error err;
        long f0 = minflt();
        double t0 = cpu_now();
        fl_status st;
        if (rec) {
            fl_reconstruction2 out;
            st = fl_reconstruct2(c->xy, c->n, NULL, &out, &err);
            t0 = cpu_now() - t0;
            fl_reconstruction2_free(&out);
        } else {
            fl_dt2 d;
            st = fl_dt2_build(c->xy, c->n, NULL, &d, &err);
            t0 = cpu_now() - t0;
            fl_dt2_free(&d);
        }
        if (st != FL_OK) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
        printf(" %.4f/%ld", t0, minflt() - f0);
        least = t0 < least ? t0 : least;
    }
    printf(" least=%.4f\n", least);
    return 0;
}

static uint64_t rng = 0x2545F4914F6CDD1Dull;
static uint64_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

static void cmd_random(int count)
{
    for (int k = 0; k < count; k++) {
        size_t n = 3000 + (size_t)(next() % 47001);
        int grid = k % 2; /* grid-snapped: many duplicates and tied keys */
        double *xy = malloc(2 * n * sizeof *xy);
        for (size_t i = 0; i < 2 * n; i++) {
            double u = (double)(next() >> 11) / 9007199254740992.0;
            xy[i] = grid ? floor(u * 200) / 200 : u;
        }
        for (size_t i = 0; i < n / 50; i++) { /* exact duplicates */
            size_t a = next() % n, b = next() % n;
            xy[2 * a] = xy[2 * b];
            xy[2 * a + 1] = xy[2 * b + 1];
        }
        uint32_t keep[4] = {0, 1, 2, 3};
        hash_case((size_t)k, xy, n, keep);
        free(xy);
    }
}

int main(int argc, char **argv)
{
    if (argc >= 4 && strcmp(argv[1], "random") == 0) {
        rng ^= strtoull(argv[2], NULL, 10) * 0x9e3779b97f4a7c15ull;
        cmd_random(atoi(argv[3]));
    } else if (argc >= 4 && (strcmp(argv[1], "time") == 0 || strcmp(argv[1], "hash") == 0)) {
        r2_set s;
        int is_time = strcmp(argv[1], "time") == 0;
        if (!is_time && argc > 4) variants = atoi(argv[4]);
        if (r2_load(argv[2], is_time ? 3 : (size_t)atol(argv[3]), &s) || s.count == 0) return 1;
        if (is_time) {
            int rc = cmd_time(&s, argv[3], argc > 4 ? atoi(argv[4]) : 1);
            r2_free(&s);
            return rc;
        }
        for (size_t k = 0; k < s.count; k++) {
            const r2_case *c = &s.cases[k];
            /* two edges of the ring (consecutive samples), as input indices */
            uint32_t inv[4] = {0, 0, 0, 0};
            for (size_t i = 0; i < c->n; i++)
                if (c->truth[i] < 4) inv[c->truth[i]] = (uint32_t)i;
            uint32_t keep[4] = {inv[0], inv[1], inv[2], inv[3]};
            hash_case(k, c->xy, c->n, keep);
        }
        r2_free(&s);
    } else {
        fprintf(stderr, "usage: recon2_cpu time FILE.xy dt|rec [K] | hash FILE.xy MIN_POINTS | "
                        "random SEED COUNT\n");
        return 2;
    }
    printf("TOTAL %zu %zu %016llx\n", runs, oks, (unsigned long long)total);
    return 0;
}

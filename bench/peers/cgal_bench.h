/* Shared driver of the CGAL peers of the Delaunay benchmarks (cgal_dt2.cpp, cgal_dt3.cpp,
 * cgal_rt3.cpp), timed with the protocol of bench/timing.h like bench/ours_delaunay.c.
 *
 * The points are read from FILE.bin (bench/gen_points.c) and converted to CGAL points before any
 * timing, so the timed region is exactly the construction `Tri t(points.begin(), points.end())`:
 * CGAL's range insertion, which spatially sorts the points (Hilbert sort in a BRIO order) and
 * inserts them with the previous vertex as the location hint, its fastest sequential way to
 * build a triangulation. The destructor runs outside the timing. Kernel:
 * Exact_predicates_inexact_constructions_kernel (filtered exact predicates, as ours are exact).
 *
 * RESULT's `vertices` is t.number_of_vertices() (duplicates merged; hidden weighted points not
 * counted), `triangles` the number of finite faces (2D) or finite cells (3D). */
#ifndef FL_BENCH_CGAL_BENCH_H
#define FL_BENCH_CGAL_BENCH_H

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

#include "../pointfile.h"
extern "C" {
#include "../timing.h"
}

template <class Tri> struct cgal_input {
    std::vector<typename Tri::Point> points;
};

template <class Tri, class Count> struct cgal_bench {
    static int build(void *ctx, const char *, void **result, size_t *vertices, size_t *cells)
    {
        auto *in = static_cast<cgal_input<Tri> *>(ctx);
        try {
            Tri *t = new Tri(in->points.begin(), in->points.end());
            *vertices = t->number_of_vertices();
            *cells = Count()(*t);
            *result = t;
            return 0;
        } catch (const std::exception &e) {
            std::fprintf(stderr, "cgal: %s\n", e.what());
            return 1;
        }
    }
    static void release(void *, void *result) { delete static_cast<Tri *>(result); }
};

/* main() of a peer: `prog FILE.bin [REPS]`; make(const double *) builds one CGAL point from
 * `dim` doubles. */
template <class Tri, class Count, class Make>
int cgal_main(int argc, char **argv, const char *name, int dim, Make make)
{
    const char *path;
    int reps;
    if (bench_parse_args(argc, argv, &path, &reps)) return 2;
    size_t n;
    double *c = bench_read_points(path, dim, &n);
    if (!c) return 1;
    cgal_input<Tri> in;
    in.points.reserve(n);
    for (size_t i = 0; i < n; i++)
        in.points.push_back(make(c + i * (size_t)dim));
    std::free(c);
    bench_reader reader = {name, cgal_bench<Tri, Count>::build, cgal_bench<Tri, Count>::release,
                           &in};
    return bench_time_reader(&reader, path, reps) ? 1 : 0;
}

#endif /* FL_BENCH_CGAL_BENCH_H */

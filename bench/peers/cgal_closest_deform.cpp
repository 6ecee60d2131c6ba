// CGAL peer of the deforming-mesh closest-point benchmark (bench/deform_eval.h, the same frames
// and queries as bench/closest_deform.c). An AABB_tree cannot refit, so every frame rebuilds it:
// the frame's Triangle_3 vector, tree.rebuild, accelerate_distance_queries; then
// closest_point_and_primitive for the frame's queries in order. Times (wall and process CPU)
// cover the rebuild and the queries. Writes PREFIX.deform.cgal.d; FRAME and RESULT lines as ours.
//   cgal_closest_deform PREFIX [FRAMES [QUERIES]]
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdio>
#include <vector>

#include "../deform_eval.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::vector<K::Triangle_3>::const_iterator Iterator;
typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;

static double cpu_now()
{
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: cgal_closest_deform PREFIX [FRAMES [QUERIES]]\n");
        return 2;
    }
    int frames = argc > 2 ? std::atoi(argv[2]) : 20;
    long nq = argc > 3 ? std::atol(argv[3]) : 10000;
    ce_mesh m;
    if (frames < 1 || nq < 1 || ce_read_mesh(argv[1], &m)) return 1;
    de_setup s;
    de_init(&s, &m);
    std::vector<double> xyz(m.v * 3), q(3 * (size_t)nq), d;
    d.reserve((size_t)frames * (size_t)nq);
    std::vector<K::Triangle_3> tris(m.t);
    Tree tree;
    double move_w = 0, move_c = 0, query_w = 0, query_c = 0, checksum = 0, build0 = 0;
    for (int f = 0; f < frames; f++) {
        de_frame(&s, &m, f, frames, xyz.data());
        de_walk(&s, q.data(), (uint64_t)nq);
        double w0 = ce_now(), c0 = cpu_now();
        auto P = [&](uint32_t i) { return K::Point_3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); };
        for (size_t t = 0; t < m.t; t++)
            tris[t] = K::Triangle_3(P(m.tri[3 * t]), P(m.tri[3 * t + 1]), P(m.tri[3 * t + 2]));
        tree.rebuild(tris.begin(), tris.end());
        tree.accelerate_distance_queries();
        double w1 = ce_now(), c1 = cpu_now(), sum = 0;
        if (f == 0) build0 = w1 - w0;
        for (long i = 0; i < nq; i++) {
            K::Point_3 p(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
            auto cp = tree.closest_point_and_primitive(p);
            d.push_back(std::sqrt(CGAL::squared_distance(p, cp.first)));
            sum += d.back();
        }
        double w2 = ce_now(), c2 = cpu_now();
        move_w += w1 - w0;
        move_c += c1 - c0;
        query_w += w2 - w1;
        query_c += c2 - c1;
        checksum += sum;
        std::printf("FRAME f=%d move_s=%.6f query_s=%.6f checksum=%.17g\n", f, w1 - w0, w2 - w1,
                    sum);
    }
    ce_write_distances(argv[1], "deform", "cgal", d.data(), d.size());
    double total = move_w + query_w;
    std::printf("RESULT method=cgal-rebuild frames=%d queries=%ld build0_s=%.6f move_s=%.6f "
                "query_s=%.6f total_s=%.6f cpu_s=%.6f qps=%.1f checksum=%.17g\n",
                frames, nq, build0, move_w, query_w, total, move_c + query_c,
                (double)frames * (double)nq / total, checksum);
    free(m.xyz);
    free(m.tri);
    return 0;
}

// CGAL peer of the closest-point evaluation (bench/closest_eval.h): an AABB_tree over the
// triangles (AABB_triangle_primitive on a vector of Triangle_3, Epick kernel) with
// accelerate_distance_queries(), then closest_point_and_primitive for every query in the given
// order. Timed separately: building (tree + distance-query acceleration), and the queries.
//   cgal_aabb PREFIX KIND [REPS]
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../closest_eval.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::vector<K::Triangle_3>::const_iterator Iterator;
typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;

int main(int argc, char **argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: cgal_aabb PREFIX KIND [REPS]\n");
        return 2;
    }
    int reps = argc > 3 ? std::atoi(argv[3]) : 3;
    ce_mesh m;
    size_t n = 0;
    double *q = ce_read_queries(argv[1], argv[2], &n);
    if (ce_read_mesh(argv[1], &m) || !q) return 1;
    std::vector<K::Triangle_3> tris;
    tris.reserve(m.t);
    auto P = [&](uint32_t i) { return K::Point_3(m.xyz[3 * i], m.xyz[3 * i + 1], m.xyz[3 * i + 2]); };
    for (size_t t = 0; t < m.t; t++)
        tris.emplace_back(P(m.tri[3 * t]), P(m.tri[3 * t + 1]), P(m.tri[3 * t + 2]));
    std::vector<double> build, query, d(n);
    for (int k = 0; k < reps; k++) {
        double t0 = ce_now();
        Tree tree(tris.begin(), tris.end());
        tree.accelerate_distance_queries();
        build.push_back(ce_now() - t0);
        t0 = ce_now();
        for (size_t i = 0; i < n; i++) {
            K::Point_3 p(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
            auto cp = tree.closest_point_and_primitive(p);
            d[i] = std::sqrt(CGAL::squared_distance(p, cp.first));
        }
        query.push_back(ce_now() - t0);
    }
    std::sort(build.begin(), build.end());
    std::sort(query.begin(), query.end());
    ce_write_distances(argv[1], argv[2], "cgal", d.data(), n);
    std::printf("RESULT method=cgal-aabb kind=%s queries=%zu build_s=%.6f query_s=%.6f\n", argv[2],
                n, build[reps / 2], query[reps / 2]);
    free(q);
    free(m.xyz);
    free(m.tri);
    return 0;
}

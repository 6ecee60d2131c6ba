/* CGAL peer of the weighted (regular) 3D benchmark: Regular_triangulation_3 of Weighted_point_3
 * (weight = squared radius, as ours) built from the range of points (see cgal_bench.h).
 *   cgal_rt3 FILE.bin [REPS]   (4 doubles a point: x y z w) */
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>

#include "cgal_bench.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Regular_triangulation_3<K> Tri;

struct count_cells {
    size_t operator()(const Tri &t) const { return t.number_of_finite_cells(); }
};

int main(int argc, char **argv)
{
    return cgal_main<Tri, count_cells>(argc, argv, "cgal_rt3", 4, [](const double *p) {
        return K::Weighted_point_3(K::Point_3(p[0], p[1], p[2]), p[3]);
    });
}

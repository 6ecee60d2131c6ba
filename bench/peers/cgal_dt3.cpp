/* CGAL peer of the 3D Delaunay benchmark: Delaunay_triangulation_3 (sequential, default data
 * structure) built from the range of points (see cgal_bench.h).
 *   cgal_dt3 FILE.bin [REPS]   (3 doubles a point) */
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cgal_bench.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_triangulation_3<K> Tri;

struct count_cells {
    size_t operator()(const Tri &t) const { return t.number_of_finite_cells(); }
};

int main(int argc, char **argv)
{
    return cgal_main<Tri, count_cells>(
        argc, argv, "cgal_dt3", 3, [](const double *p) { return K::Point_3(p[0], p[1], p[2]); });
}

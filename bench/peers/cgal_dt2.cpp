/* CGAL peer of the 2D Delaunay benchmark: Delaunay_triangulation_2 built from the range of
 * points (see cgal_bench.h).   cgal_dt2 FILE.bin [REPS]   (2 doubles a point) */
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cgal_bench.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_triangulation_2<K> Tri;

struct count_faces {
    size_t operator()(const Tri &t) const { return t.number_of_faces(); }
};

int main(int argc, char **argv)
{
    return cgal_main<Tri, count_faces>(argc, argv, "cgal_dt2", 2,
                                       [](const double *p) { return K::Point_2(p[0], p[1]); });
}

// The CGAL peer of `flintstone hausdorff` (bench/workloads/hausdorff.sh), Debian libcgal-dev
// (CGAL 5.5), sequential, Exact_predicates_inexact_constructions_kernel, Surface_mesh:
//
//   cgal_hausdorff simplify IN OUT RATIO   edge-collapse simplification (Surface_mesh_simplification
//                                          with the default Lindstrom-Turk policies) down to RATIO of
//                                          the edges; writes OUT (.off)
//   cgal_hausdorff bounded A B ERROR       PMP::bounded_error_symmetric_Hausdorff_distance(A, B,
//                                          ERROR): an estimate within ERROR of the true distance
//   cgal_hausdorff approx A B N            PMP::approximate_symmetric_Hausdorff_distance with N
//                                          random points per unit area on each mesh (a lower
//                                          estimate, no bound)
//
// The timed region excludes reading the files. Prints one line:
//   RESULT peer=<what> value=<distance> seconds=<wall>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace SMS = CGAL::Surface_mesh_simplification;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

static double now()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

static bool read(const char *path, Mesh &m)
{
    if (!CGAL::IO::read_polygon_mesh(path, m) || !CGAL::is_triangle_mesh(m)) {
        std::fprintf(stderr, "cgal_hausdorff: cannot read %s as a triangle mesh\n", path);
        return false;
    }
    return true;
}

int main(int argc, char **argv)
{
    if (argc != 5) {
        std::fprintf(stderr, "usage: cgal_hausdorff simplify|bounded|approx A B|OUT VALUE\n");
        return 1;
    }
    const char *mode = argv[1];
    double value = std::atof(argv[4]);
    Mesh a, b;
    if (!read(argv[2], a)) return 2;
    if (!std::strcmp(mode, "simplify")) {
        SMS::Count_ratio_stop_predicate<Mesh> stop(value);
        double t0 = now();
        int removed = SMS::edge_collapse(a, stop);
        a.collect_garbage();
        double t = now() - t0;
        if (!CGAL::IO::write_polygon_mesh(argv[3], a, CGAL::parameters::stream_precision(17))) {
            std::fprintf(stderr, "cgal_hausdorff: cannot write %s\n", argv[3]);
            return 4;
        }
        std::printf("RESULT peer=edge_collapse removed=%d faces=%zu seconds=%.6f\n", removed,
                    (size_t)a.number_of_faces(), t);
        return 0;
    }
    if (!read(argv[3], b)) return 2;
    double t0 = now(), h;
    if (!std::strcmp(mode, "bounded")) {
        h = PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(a, b, value);
    } else if (!std::strcmp(mode, "approx")) {
        h = PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(
            a, b, CGAL::parameters::number_of_points_per_area_unit(value),
            CGAL::parameters::number_of_points_per_area_unit(value));
    } else {
        std::fprintf(stderr, "cgal_hausdorff: unknown mode %s\n", mode);
        return 1;
    }
    std::printf("RESULT peer=%s value=%.17g seconds=%.6f\n", mode, h, now() - t0);
    return 0;
}

/* CGAL peer of the skin benchmark (bench/workloads/skin.sh): CGAL::make_skin_surface_mesh_3
 * (Skin_surface_3, Kruithof & Vegter's mesher) of a ball file into a Polyhedron_3.
 *   cgal_skin BALLS.xyzw T [OUT.off]
 * BALLS: one "x y z w" line a ball (w = squared radius, '#' comments), as flintstone reads.
 * Prints "RESULT seconds=<wall> cpu=<process CPU> vertices=<V> faces=<F>"; the timed region is
 * the mesher alone (the balls are parsed before, the mesh written after). Kernel:
 * Exact_predicates_inexact_constructions_kernel. */
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/make_skin_surface_mesh_3.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <list>
#include <sstream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Bare_point;
typedef K::Weighted_point_3 Weighted_point;
typedef CGAL::Polyhedron_3<K> Polyhedron;

int main(int argc, char **argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: cgal_skin BALLS.xyzw T [OUT.off]\n");
        return 1;
    }
    std::ifstream in(argv[1]);
    std::list<Weighted_point> balls;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ss(line);
        double x, y, z, w;
        if (ss >> x >> y >> z >> w) balls.push_back(Weighted_point(Bare_point(x, y, z), w));
    }
    double t = std::atof(argv[2]);
    Polyhedron p;
    timespec c0, c1;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
    auto t0 = std::chrono::steady_clock::now();
    // grow_balls = false: the skin of the balls as given (CGAL grows them by 1/t by default)
    CGAL::make_skin_surface_mesh_3(p, balls.begin(), balls.end(), t, 0, false);
    auto t1 = std::chrono::steady_clock::now();
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
    double cpu = (double)(c1.tv_sec - c0.tv_sec) + 1e-9 * (double)(c1.tv_nsec - c0.tv_nsec);
    std::printf("RESULT seconds=%.6f cpu=%.6f vertices=%zu faces=%zu\n",
                std::chrono::duration<double>(t1 - t0).count(), cpu, p.size_of_vertices(),
                p.size_of_facets());
    if (argc > 3) {
        std::ofstream out(argv[3]);
        out.precision(17);
        out << p;
    }
    return 0;
}

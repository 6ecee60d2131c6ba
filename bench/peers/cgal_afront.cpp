/* CGAL peer of the 3D reconstruction benchmark (bench/workloads/reconstruct3.sh): CGAL's
 * Advancing Front surface reconstruction (Cohen-Steiner & Da, the free function
 * CGAL::advancing_front_surface_reconstruction with its default priority, Debian libcgal-dev)
 * on the same scattered points as `flintstone reconstruct`.
 *   cgal_afront POINTS.xyz OUT.off
 * Reads the first three numbers of every line, times the reconstruction alone (best of 3,
 * steady_clock), writes the input points and the facets as OFF (so `flintstone check` can measure
 * closedness, genus and the points left unused as unreferenced vertices) and prints one JSON
 * line: points, faces, seconds. */
#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef std::array<std::size_t, 3> Facet;

int main(int argc, char **argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: cgal_afront POINTS.xyz OUT.off\n");
        return 2;
    }
    std::ifstream in(argv[1]);
    if (!in) {
        std::fprintf(stderr, "cgal_afront: cannot read %s\n", argv[1]);
        return 1;
    }
    std::vector<Point> pts;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        double x, y, z;
        if (ls >> x >> y >> z) pts.emplace_back(x, y, z);
    }
    std::vector<Facet> facets;
    double best = 1e300;
    for (int rep = 0; rep < 3; rep++) {
        facets.clear();
        auto t0 = std::chrono::steady_clock::now();
        CGAL::advancing_front_surface_reconstruction(pts.begin(), pts.end(),
                                                     std::back_inserter(facets));
        std::chrono::duration<double> dt = std::chrono::steady_clock::now() - t0;
        if (dt.count() < best) best = dt.count();
    }
    std::FILE *f = std::fopen(argv[2], "w");
    if (!f) return 1;
    std::fprintf(f, "OFF\n%zu %zu 0\n", pts.size(), facets.size());
    for (const Point &p : pts)
        std::fprintf(f, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    for (const Facet &t : facets)
        std::fprintf(f, "3 %zu %zu %zu\n", t[0], t[1], t[2]);
    std::fclose(f);
    std::printf("{\"points\":%zu,\"faces\":%zu,\"seconds\":%.6f}\n", pts.size(), facets.size(),
                best);
    return 0;
}

// CGAL peer of the 2D boundary-construction evaluation (bench/recon2_eval.h): the alpha shape
// (Alpha_shape_2, regularized) at CGAL's optimal alpha, find_optimal_alpha(1): the smallest
// alpha whose shape has one solid component with every point on its boundary or inside. Its
// boundary edges (REGULAR edges) are scored like ours. Timed: building the alpha shape (its
// Delaunay triangulation and alpha spectrum) plus finding the optimal alpha.
//   cgal_alpha2 RINGS.xy [MIN_POINTS [EDGES_DIR|-]]   (EDGES_DIR: bench/recon2_eval.h)
#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <chrono>
#include <utility>
#include <vector>

#include "../recon2_eval.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K> Vbi;
typedef CGAL::Alpha_shape_vertex_base_2<K, Vbi> Vb;
typedef CGAL::Alpha_shape_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Delaunay_triangulation_2<K, Tds> Dt;
typedef CGAL::Alpha_shape_2<Dt> Alpha;

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: cgal_alpha2 RINGS.xy [MIN_POINTS [EDGES_DIR|-]]\n");
        return 2;
    }
    r2_set s;
    if (r2_load(argv[1], argc > 2 ? (size_t)std::atol(argv[2]) : 20, &s)) return 1;
    r2_score sc = {};
    FILE *out = r2_edges_open(argc > 3 ? argv[3] : nullptr, "cgal-alpha-shape-optimal");
    for (size_t k = 0; k < s.count; k++) {
        const r2_case &c = s.cases[k];
        std::vector<std::pair<K::Point_2, uint32_t>> pts;
        pts.reserve(c.n);
        for (size_t i = 0; i < c.n; i++)
            pts.emplace_back(K::Point_2(c.xy[2 * i], c.xy[2 * i + 1]), (uint32_t)i);
        auto t0 = std::chrono::steady_clock::now();
        Alpha a(pts.begin(), pts.end(), 0, Alpha::REGULARIZED);
        auto opt = a.find_optimal_alpha(1);
        a.set_alpha(*opt);
        sc.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::vector<uint32_t> edges;
        for (auto e = a.alpha_shape_edges_begin(); e != a.alpha_shape_edges_end(); ++e) {
            auto f = e->first;
            int i = e->second;
            edges.push_back(f->vertex(Dt::cw(i))->info());
            edges.push_back(f->vertex(Dt::ccw(i))->info());
        }
        r2_score_case(&sc, &c, edges.data(), edges.size() / 2);
        r2_edges_write(out, k, edges.data(), edges.size() / 2);
    }
    if (out) std::fclose(out);
    r2_print(&sc, "cgal-alpha-shape-optimal");
    r2_free(&s);
    return 0;
}

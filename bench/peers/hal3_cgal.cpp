// CGAL peer of the 3D flintstone benchmark (bench/eval_hal3.c, docs/hal.md "3D"): the same
// binary mesh and query files (bench/closest_eval.h format), Surface_mesh, Epick kernel.
//   hal3_cgal inside PREFIX [REPS]   an AABB_tree over the faces (AABB_face_graph_triangle_
//       primitive, built explicitly so the build is timed apart from the queries), then
//       Side_of_triangle_mesh(tree) on every query of PREFIX.random.q; writes
//       PREFIX.random.cgal.a (0 outside, 1 inside, 2 on the surface)
//   hal3_cgal intersect PREFIX OTHER [REPS]   Polygon_mesh_processing::do_intersect of the two
//       surfaces (it builds its own box structure inside the call: the time is all of it)
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "../closest_eval.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;

static bool load(const char *prefix, Mesh &out)
{
    ce_mesh m;
    if (ce_read_mesh(prefix, &m)) return false;
    std::vector<Mesh::Vertex_index> vs;
    for (size_t i = 0; i < m.v; i++)
        vs.push_back(out.add_vertex(K::Point_3(m.xyz[3 * i], m.xyz[3 * i + 1], m.xyz[3 * i + 2])));
    for (size_t t = 0; t < m.t; t++)
        out.add_face(vs[m.tri[3 * t]], vs[m.tri[3 * t + 1]], vs[m.tri[3 * t + 2]]);
    free(m.xyz);
    free(m.tri);
    return true;
}

static int inside(const char *prefix, int reps)
{
    Mesh mesh;
    size_t n = 0;
    double *q = ce_read_queries(prefix, "random", &n);
    if (!q || !load(prefix, mesh)) return 1;
    std::vector<K::Point_3> pts;
    pts.reserve(n);
    for (size_t i = 0; i < n; i++) pts.emplace_back(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
    std::vector<double> build, query;
    std::vector<unsigned char> a(n);
    for (int k = 0; k < reps; k++) {
        double t0 = ce_now();
        Tree tree(faces(mesh).first, faces(mesh).second, mesh);
        tree.build();
        build.push_back(ce_now() - t0);
        CGAL::Side_of_triangle_mesh<Mesh, K> side(tree);
        t0 = ce_now();
        for (size_t i = 0; i < n; i++) {
            CGAL::Bounded_side s = side(pts[i]);
            a[i] = s == CGAL::ON_BOUNDED_SIDE ? 1 : s == CGAL::ON_BOUNDARY ? 2 : 0;
        }
        query.push_back(ce_now() - t0);
    }
    std::sort(build.begin(), build.end());
    std::sort(query.begin(), query.end());
    char path[1024];
    std::snprintf(path, sizeof path, "%s.random.cgal.a", prefix);
    FILE *f = std::fopen(path, "wb");
    if (!f || std::fwrite(a.data(), 1, n, f) != n) return 1;
    std::fclose(f);
    size_t in = std::count(a.begin(), a.end(), 1);
    std::printf("RESULT method=cgal-side-of-triangle-mesh queries=%zu build_s=%.6f query_s=%.6f "
                "inside=%zu\n",
                n, build[reps / 2], query[reps / 2], in);
    free(q);
    return 0;
}

static int intersect(const char *prefix, const char *other, int reps)
{
    Mesh a, b;
    char path[1024];
    std::snprintf(path, sizeof path, "%s-%s", prefix, other);
    if (!load(prefix, a) || !load(path, b)) return 1;
    std::vector<double> t;
    bool hit = false;
    for (int k = 0; k < reps; k++) {
        double t0 = ce_now();
        hit = CGAL::Polygon_mesh_processing::do_intersect(a, b);
        t.push_back(ce_now() - t0);
    }
    std::sort(t.begin(), t.end());
    std::printf("RESULT method=cgal-do-intersect intersect=%d query_s=%.6f\n", hit ? 1 : 0,
                t[reps / 2]);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 3 && std::strcmp(argv[1], "inside") == 0)
        return inside(argv[2], argc > 3 ? std::atoi(argv[3]) : 3);
    if (argc >= 4 && std::strcmp(argv[1], "intersect") == 0)
        return intersect(argv[2], argv[3], argc > 4 ? std::atoi(argv[4]) : 3);
    std::fprintf(stderr, "usage: hal3_cgal inside PREFIX [REPS] | intersect PREFIX OTHER [REPS]\n");
    return 2;
}

// The reference for `flintstone check` (bench/workloads/check_mesh.sh): the same questions about
// a mesh file answered by CGAL (Debian libcgal-dev), printed as one JSON line per file.
//
//   cgal_check FILE...            the validation (below)
//   cgal_check --timing FILE...   what a CGAL user would run to check a triangle mesh file:
//                                 CGAL::IO::read_polygon_mesh into a Surface_mesh, then the
//                                 mesh checks below (no soup figures: those are our own code)
//   cgal_check --si REPS FILE     PMP::self_intersections alone, REPS timed runs (medians)
//
// The validation, and which CGAL function computes what:
//  - the file is read as a polygon soup (CGAL::IO::read_polygon_soup; STL points are merged
//    by the reader, like our STL reader's weld) and every polygon is fan-triangulated from its
//    first corner, (i0, i(k-1), ik), which is what our readers do;
//  - from the soup itself: vertices, faces, distinct undirected edges and how many faces each
//    has (closed: every edge in exactly two faces), unreferenced points, degenerate faces (a
//    repeated index, or CGAL::collinear), area (soup_area, for files CGAL cannot make a mesh of),
//    self-intersecting pairs (soup_self_intersections, see soup_self_intersections below);
//  - PMP::is_polygon_soup_a_polygon_mesh says whether the soup is an oriented combinatorial
//    manifold as given; if not, PMP::orient_polygon_soup tries to reorient it and says whether
//    it had to duplicate points (non-manifold vertex or edge, or not orientable; the number of
//    added points is points_duplicated, the vertices it reports non-manifold are
//    nonmanifold_vertices). When it did not, the soup becomes a CGAL::Surface_mesh
//    (PMP::polygon_soup_to_polygon_mesh) with the same vertices, and on that mesh:
//    CGAL::is_closed, PMP::connected_components (faces joined through edges), V - E + F per
//    component and the genus of each closed component, PMP::is_degenerate_triangle_face,
//    PMP::self_intersections (pairs (f, f) are CGAL's way of flagging a degenerate face and
//    are counted apart), PMP::area and, when closed, PMP::volume.
//  - wall-clock seconds in this process: read_s (soup and triangulation; with --timing, the
//    whole read_polygon_mesh), soup_s (the soup figures), mesh_s (polygon-mesh test,
//    reorientation if needed, Surface_mesh construction), check_s (closed, components, Euler,
//    degenerate, area, volume on the Surface_mesh), self_intersections_s.
// Nothing is repaired beyond the reorientation, so a mesh CGAL cannot hold as a Surface_mesh
// gets `"surface_mesh": false` and no mesh figures; when the soup cut at its singularities is
// a mesh, its components and V - E + F are printed as split_components and split_euler, and
// its components joined again where a point was copied as split_components_joined.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef std::vector<std::size_t> Polygon;

static double now()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Figures computed from the triangle soup alone (valid for every file that reads).
struct SoupFigures {
    std::size_t edges = 0, boundary_edges = 0, nonmanifold_edges = 0;
    std::size_t unreferenced = 0, degenerate = 0;
    double area = 0; // sum of sqrt(CGAL::squared_area), as PMP::area does face by face
    bool closed = false;
};

static SoupFigures soup_figures(const std::vector<Point> &pts, const std::vector<Polygon> &tris)
{
    SoupFigures s;
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_faces;
    std::vector<char> used(pts.size(), 0);
    for (const Polygon &t : tris) {
        for (int k = 0; k < 3; k++) {
            std::size_t a = t[k], b = t[(k + 1) % 3];
            edge_faces[std::make_pair(std::min(a, b), std::max(a, b))]++;
            used[a] = 1;
        }
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
            CGAL::collinear(pts[t[0]], pts[t[1]], pts[t[2]]))
            s.degenerate++;
        s.area += std::sqrt(CGAL::squared_area(pts[t[0]], pts[t[1]], pts[t[2]]));
    }
    s.edges = edge_faces.size();
    for (const auto &e : edge_faces) {
        if (e.second == 1) s.boundary_edges++;
        if (e.second >= 3) s.nonmanifold_edges++;
    }
    for (char u : used)
        s.unreferenced += !u;
    s.closed = !tris.empty() && s.boundary_edges == 0 && s.nonmanifold_edges == 0;
    for (const auto &e : edge_faces)
        if (e.second != 2) s.closed = false;
    return s;
}

// Self-intersecting pairs of a triangle soup: for files CGAL cannot hold as a Surface_mesh
// (PMP::self_intersections needs one), and as a cross-check where it can. The candidate pairs
// come from CGAL::box_self_intersection_d on closed boxes, as in PMP::self_intersections, and
// each pair is decided as PMP's do_faces_intersect decides it, with shared vertices recognised
// by index instead of by halfedge: a shared edge uv intersects iff the four points are
// coplanar and the third corners lie on the same side of uv; one shared vertex v iff the side
// opposite v of either triangle meets the other; none iff the triangles meet. A face repeated
// (three shared indices; a Surface_mesh cannot hold it) counts, as ours does. Degenerate faces
// take no part (PMP pairs them with themselves instead).
typedef CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t,
                                                  CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>
    Soup_box;

static bool soup_pair_intersects(const std::vector<Point> &p, const Polygon &a, const Polygon &b)
{
    int shared = 0, ia = -1, ib = -1; // ia, ib: positions of the (last) shared index
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (a[i] == b[j]) {
                shared++;
                ia = i;
                ib = j;
            }
    if (shared == 3) return true;
    if (shared == 2) {
        int ra = 0, rb = 0; // the corners that are not shared
        for (int i = 0; i < 3; i++) {
            if (a[i] != b[0] && a[i] != b[1] && a[i] != b[2]) ra = i;
            if (b[i] != a[0] && b[i] != a[1] && b[i] != a[2]) rb = i;
        }
        const Point &u = p[a[(ra + 1) % 3]], &v = p[a[(ra + 2) % 3]];
        return CGAL::coplanar(u, v, p[a[ra]], p[b[rb]]) &&
               CGAL::coplanar_orientation(u, v, p[a[ra]], p[b[rb]]) == CGAL::POSITIVE;
    }
    K::Triangle_3 ta(p[a[0]], p[a[1]], p[a[2]]), tb(p[b[0]], p[b[1]], p[b[2]]);
    if (shared == 1)
        return CGAL::do_intersect(ta, K::Segment_3(p[b[(ib + 1) % 3]], p[b[(ib + 2) % 3]])) ||
               CGAL::do_intersect(tb, K::Segment_3(p[a[(ia + 1) % 3]], p[a[(ia + 2) % 3]]));
    return CGAL::do_intersect(ta, tb);
}

static std::size_t soup_self_intersections(const std::vector<Point> &p,
                                           const std::vector<Polygon> &tris)
{
    std::vector<Soup_box> boxes;
    for (std::size_t t = 0; t < tris.size(); t++) {
        const Polygon &f = tris[t];
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] ||
            CGAL::collinear(p[f[0]], p[f[1]], p[f[2]]))
            continue;
        boxes.push_back(Soup_box(p[f[0]].bbox() + p[f[1]].bbox() + p[f[2]].bbox(), t));
    }
    std::vector<const Soup_box *> ptrs;
    for (const Soup_box &b : boxes)
        ptrs.push_back(&b);
    std::size_t count = 0;
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(
        ptrs.begin(), ptrs.end(), [&](const Soup_box *x, const Soup_box *y) {
            count += soup_pair_intersects(p, tris[x->info()], tris[y->info()]);
        });
    return count;
}

// Euler characteristic and closedness of each connected component of a Surface_mesh.
struct ComponentFigures {
    std::vector<long long> v, e, f;
    std::vector<char> open;
};

static ComponentFigures component_figures(const Mesh &m,
                                          Mesh::Property_map<Mesh::Face_index, std::size_t> comp,
                                          std::size_t n)
{
    ComponentFigures c;
    c.v.assign(n, 0);
    c.e.assign(n, 0);
    c.f.assign(n, 0);
    c.open.assign(n, 0);
    for (Mesh::Face_index f : m.faces())
        c.f[comp[f]]++;
    for (Mesh::Edge_index e : m.edges()) {
        Mesh::Halfedge_index h = m.halfedge(e);
        bool border = m.is_border(h) || m.is_border(m.opposite(h));
        if (m.is_border(h)) h = m.opposite(h);
        std::size_t c0 = comp[m.face(h)];
        c.e[c0]++;
        if (border) c.open[c0] = 1;
    }
    for (Mesh::Vertex_index v : m.vertices()) {
        for (Mesh::Halfedge_index h : CGAL::halfedges_around_target(v, m)) {
            if (!m.is_border(h)) {
                c.v[comp[m.face(h)]]++;
                break;
            }
        }
    }
    return c;
}

// Counts what orient_polygon_soup reports: vertices whose link (the polygons around them,
// joined through edges with two compatibly oriented polygons) has more than one component.
// Also keeps each added point with the point it copies, to join the pieces again.
struct Singularity_counter : public PMP::Default_orientation_visitor {
    std::size_t *nonmanifold_vertices;
    std::vector<std::pair<std::size_t, std::size_t>> *copies;
    Singularity_counter(std::size_t *n, std::vector<std::pair<std::size_t, std::size_t>> *c)
        : nonmanifold_vertices(n), copies(c)
    {
    }
    void non_manifold_vertex(std::size_t, std::size_t) { ++*nonmanifold_vertices; }
    void duplicated_vertex(std::size_t from, std::size_t to) { copies->emplace_back(from, to); }
};

static std::size_t find_root(std::vector<std::size_t> &parent, std::size_t i)
{
    while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
    return i;
}

// Components of the cut mesh joined again through the points orient_polygon_soup copied:
// components through shared vertices, as ours counts them. polygon_soup_to_polygon_mesh makes
// vertex i of point i (checked; returns 0 if not).
static std::size_t
vertex_joined_components(const Mesh &m, Mesh::Property_map<Mesh::Face_index, std::size_t> comp,
                         std::size_t ncomp, const std::vector<Point> &pts,
                         const std::vector<std::pair<std::size_t, std::size_t>> &copies)
{
    if (m.number_of_vertices() != pts.size()) return 0;
    std::vector<std::size_t> parent(ncomp);
    for (std::size_t i = 0; i < ncomp; i++)
        parent[i] = i;
    std::size_t joined = ncomp;
    for (const auto &cp : copies) {
        Mesh::Vertex_index a(static_cast<Mesh::size_type>(cp.first)),
            b(static_cast<Mesh::size_type>(cp.second));
        if (m.point(a) != pts[cp.first] || m.point(b) != pts[cp.second]) return 0;
        Mesh::Halfedge_index ha = m.halfedge(a), hb = m.halfedge(b);
        if (m.is_border(ha)) ha = m.opposite(m.next(ha));
        if (m.is_border(hb)) hb = m.opposite(m.next(hb));
        std::size_t ra = find_root(parent, comp[m.face(ha)]),
                    rb = find_root(parent, comp[m.face(hb)]);
        if (ra != rb) {
            parent[ra] = rb;
            joined--;
        }
    }
    return joined;
}

static void json_bool(const char *key, bool b)
{
    std::printf(",\"%s\":%s", key, b ? "true" : "false");
}

// The checks on a Surface_mesh; prints the rest of the JSON object (from a leading comma) and
// closes it. t_read and t_mesh are the seconds already spent getting m.
static void mesh_checks(Mesh &m, double t_read, double t_soup, double t_mesh)
{
    double t0 = now();
    bool closed = CGAL::is_closed(m);
    auto comp = m.add_property_map<Mesh::Face_index, std::size_t>("f:cc", 0).first;
    std::size_t ncomp = PMP::connected_components(m, comp);
    ComponentFigures c = component_figures(m, comp, ncomp);
    // Summed over the components, so that isolated vertices (polygon_soup_to_polygon_mesh
    // makes a vertex of every point, used or not) do not count: ours counts referenced ones.
    long long euler = 0;
    for (std::size_t i = 0; i < ncomp; i++)
        euler += c.v[i] - c.e[i] + c.f[i];
    std::size_t degenerate = 0;
    for (Mesh::Face_index f : m.faces())
        degenerate += PMP::is_degenerate_triangle_face(f, m);
    double area = PMP::area(m);
    double volume = closed ? PMP::volume(m) : NAN;
    double t_check = now() - t0;

    t0 = now();
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
    PMP::self_intersections(m, std::back_inserter(pairs));
    std::size_t si = 0, si_degenerate = 0;
    for (const auto &p : pairs)
        (p.first == p.second ? si_degenerate : si)++;
    double t_si = now() - t0;

    json_bool("mesh_closed", closed);
    std::printf(",\"mesh_vertices\":%zu,\"mesh_edges\":%zu,\"mesh_faces\":%zu,\"components\":%zu,"
                "\"euler\":%lld,\"component_genus\":[",
                (std::size_t)m.number_of_vertices(), (std::size_t)m.number_of_edges(),
                (std::size_t)m.number_of_faces(), ncomp, euler);
    for (std::size_t i = 0; i < ncomp; i++) {
        long long chi = c.v[i] - c.e[i] + c.f[i];
        if (c.open[i])
            std::printf("%snull", i ? "," : "");
        else
            std::printf("%s%lld", i ? "," : "", (2 - chi) / 2);
    }
    std::printf("],\"component_euler\":[");
    for (std::size_t i = 0; i < ncomp; i++)
        std::printf("%s%lld", i ? "," : "", c.v[i] - c.e[i] + c.f[i]);
    std::printf("],\"mesh_degenerate_faces\":%zu,\"self_intersections\":%zu,"
                "\"self_intersections_degenerate\":%zu,\"area\":%.17g",
                degenerate, si, si_degenerate, area);
    if (closed)
        std::printf(",\"volume\":%.17g", volume);
    else
        std::printf(",\"volume\":null");
    std::printf(",\"read_s\":%.6f,\"soup_s\":%.6f,\"mesh_s\":%.6f,\"check_s\":%.6f,"
                "\"self_intersections_s\":%.6f}\n",
                t_read, t_soup, t_mesh, t_check, t_si);
}

// The validation: soup figures, then the mesh checks when CGAL can hold the soup as a mesh.
static int check_file(const char *path)
{
    double t0 = now();
    std::vector<Point> pts;
    std::vector<Polygon> polys;
    if (!CGAL::IO::read_polygon_soup(std::string(path), pts, polys)) {
        std::printf("{\"file\":\"%s\",\"error\":\"CGAL::IO::read_polygon_soup failed\"}\n", path);
        return 1;
    }
    std::vector<Polygon> tris;
    std::size_t non_triangles = 0;
    for (const Polygon &p : polys) {
        if (p.size() != 3) non_triangles++;
        for (std::size_t k = 2; k < p.size(); k++)
            tris.push_back(Polygon{p[0], p[k - 1], p[k]});
    }
    double t_read = now() - t0;

    t0 = now();
    SoupFigures s = soup_figures(pts, tris);
    std::size_t soup_si = soup_self_intersections(pts, tris);
    double t_soup = now() - t0;

    t0 = now();
    bool as_given = PMP::is_polygon_soup_a_polygon_mesh(tris);
    bool reoriented = false, mesh_ok = as_given;
    std::size_t nonmanifold_vertices = 0;
    std::vector<std::pair<std::size_t, std::size_t>> copies;
    std::vector<Point> opts;
    std::vector<Polygon> otris;
    // orient_polygon_soup does not terminate on some soups with a face that repeats an index
    // (seen on random soups; CGAL expects PMP::repair_polygon_soup first), so such soups are
    // not reoriented and get no CGAL mesh figures.
    std::size_t repeated = 0;
    for (const Polygon &t : tris)
        repeated += t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
    if (!as_given && !tris.empty() && repeated == 0) {
        opts = pts;
        otris = tris;
        reoriented = PMP::orient_polygon_soup(
            opts, otris,
            CGAL::parameters::visitor(Singularity_counter(&nonmanifold_vertices, &copies)));
        mesh_ok = reoriented && PMP::is_polygon_soup_a_polygon_mesh(otris);
    }
    std::printf("{\"file\":\"%s\",\"vertices\":%zu,\"faces\":%zu,\"polygons\":%zu,"
                "\"non_triangle_polygons\":%zu,\"edges\":%zu,\"boundary_edges\":%zu,"
                "\"nonmanifold_edges\":%zu,\"unreferenced_vertices\":%zu,\"degenerate_faces\":%zu,"
                "\"soup_area\":%.17g,\"soup_self_intersections\":%zu",
                path, pts.size(), tris.size(), polys.size(), non_triangles, s.edges,
                s.boundary_edges, s.nonmanifold_edges, s.unreferenced, s.degenerate, s.area,
                soup_si);
    json_bool("closed", s.closed);
    json_bool("polygon_mesh_as_given", as_given);
    json_bool("reoriented_without_split", reoriented);
    json_bool("surface_mesh", mesh_ok && !tris.empty());
    std::printf(",\"repeated_index_faces\":%zu", repeated);
    if (repeated == 0)
        std::printf(",\"points_duplicated\":%zu,\"nonmanifold_vertices\":%zu",
                    opts.empty() ? 0 : opts.size() - pts.size(), nonmanifold_vertices);
    if (!mesh_ok || tris.empty()) {
        // orient_polygon_soup cut the surface at its singular vertices (and edges). When the
        // result is a polygon mesh, its components are the original soup's faces joined
        // through edges, and its V - E + F exceeds the soup's by the points added.
        if (!otris.empty() && PMP::is_polygon_soup_a_polygon_mesh(otris)) {
            Mesh split;
            PMP::polygon_soup_to_polygon_mesh(opts, otris, split);
            auto comp = split.add_property_map<Mesh::Face_index, std::size_t>("f:cc", 0).first;
            std::size_t ncomp = PMP::connected_components(split, comp);
            ComponentFigures c = component_figures(split, comp, ncomp);
            long long euler = 0;
            for (std::size_t i = 0; i < ncomp; i++)
                euler += c.v[i] - c.e[i] + c.f[i];
            std::printf(",\"split_components\":%zu,\"split_euler\":%lld,"
                        "\"split_components_joined\":%zu",
                        ncomp, euler, vertex_joined_components(split, comp, ncomp, opts, copies));
        }
        std::printf(",\"read_s\":%.6f,\"soup_s\":%.6f,\"mesh_s\":%.6f}\n", t_read, t_soup,
                    now() - t0);
        return 0;
    }
    Mesh m;
    if (as_given)
        PMP::polygon_soup_to_polygon_mesh(pts, tris, m);
    else
        PMP::polygon_soup_to_polygon_mesh(opts, otris, m);
    mesh_checks(m, t_read, t_soup, now() - t0);
    return 0;
}

// --timing: what a CGAL user checking a triangle mesh file would run. CGAL::IO::read_polygon_mesh
// builds the Surface_mesh face by face (Euler::add_face refuses what it cannot hold), then the
// same checks; no soup figures (those are our own code, not CGAL's).
static int time_file(const char *path)
{
    double t0 = now();
    Mesh m;
    if (!CGAL::IO::read_polygon_mesh(std::string(path), m) || !CGAL::is_triangle_mesh(m)) {
        std::printf("{\"file\":\"%s\",\"error\":\"not a triangle Surface_mesh\"}\n", path);
        return 1;
    }
    double t_read = now() - t0;
    std::printf("{\"file\":\"%s\",\"vertices\":%zu,\"faces\":%zu", path,
                (std::size_t)m.number_of_vertices(), (std::size_t)m.number_of_faces());
    mesh_checks(m, t_read, 0, 0);
    return 0;
}

// --si REPS: PMP::self_intersections alone on a mesh read once (the counterpart of
// bench/ours_check.c): one untimed warm-up, then REPS runs; medians of wall and process CPU time.
static double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static int time_self_intersections(const char *path, int reps)
{
    Mesh m;
    if (!CGAL::IO::read_polygon_mesh(std::string(path), m) || !CGAL::is_triangle_mesh(m)) {
        std::printf("{\"file\":\"%s\",\"error\":\"not a triangle Surface_mesh\"}\n", path);
        return 1;
    }
    std::vector<double> wall, cpu;
    std::size_t count = 0;
    for (int r = -1; r < reps; r++) {
        std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
        double w0 = now();
        std::clock_t c0 = std::clock();
        PMP::self_intersections(m, std::back_inserter(pairs));
        if (r < 0) continue;
        cpu.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
        wall.push_back(now() - w0);
        count = pairs.size();
    }
    std::printf("{\"file\":\"%s\",\"reps\":%d,\"si_wall_s\":%.6f,\"si_cpu_s\":%.6f,"
                "\"self_intersections\":%zu}\n",
                path, reps, median(wall), median(cpu), count);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: cgal_check [--timing] FILE... | cgal_check --si REPS FILE\n");
        return 2;
    }
    if (std::string(argv[1]) == "--si" && argc == 4)
        return time_self_intersections(argv[3], std::atoi(argv[2]) > 0 ? std::atoi(argv[2]) : 1);
    bool timing = std::string(argv[1]) == "--timing";
    int failed = 0;
    for (int i = timing ? 2 : 1; i < argc; i++)
        failed |= timing ? time_file(argv[i]) : check_file(argv[i]);
    return failed;
}

// Approximation error per triangle count (docs/hal.md "3D", bench/workloads/hal3.sh): the
// adaptive flintstone approximation (fl_hal3_approximate_error) at bounds e = R/10, R/20, ...
// (R = radius of the level-0 ball) against meshoptimizer's QEM edge-collapse simplifier
// (meshopt_simplify, Debian libmeshoptimizer-dev) asked for the same triangle count with no
// error limit. Both outputs keep a subset of the input's vertices. The error of each is its
// symmetric Hausdorff distance to the input, by our certified fl_hausdorff_meshes (upper end of
// the interval; precision 1e-4 of the diagonal), and the directed distance from the input to
// the approximation, the side the flintstone bound certifies (h_in <= bound up to that
// precision). Prints one QEM line per bound, values / R.
//   hal3_qem MESH
#include <meshoptimizer.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "flintstone.h"

/* h[0] = symmetric distance, h[1] = h(b, a) (input to approximation: what the flintstone
 * bound certifies), upper ends of the certified intervals; NAN on failure. */
static void hausdorff(const fl_mesh *a, const fl_mesh *b, double h[2])
{
    fl_hausdorff_options opt = {};
    opt.relative = 1e-4;
    opt.both_directions = 1;
    fl_hausdorff_result r;
    fl_error err;
    if (fl_hausdorff_meshes(a, b, &opt, &r, &err)) {
        std::fprintf(stderr, "hausdorff: %s\n", err.message);
        h[0] = h[1] = NAN;
        return;
    }
    h[0] = r.hausdorff[1];
    h[1] = r.h_ba[1];
    fl_hausdorff_result_free(&r);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: hal3_qem MESH\n");
        return 2;
    }
    fl_mesh m;
    fl_error err;
    fl_hal3 hal;
    if (fl_read_mesh(argv[1], &m, &err) || fl_hal3_build(&m, NULL, &hal, &err)) {
        std::fprintf(stderr, "%s: %s\n", argv[1], err.message);
        return 1;
    }
    double R = std::sqrt(hal.ball[3]);
    std::vector<float> pos(3 * m.vertex_count);
    for (size_t i = 0; i < pos.size(); i++) pos[i] = (float)m.xyz[i];
    std::vector<unsigned> idx(m.tri, m.tri + 3 * m.triangle_count), out(idx.size());
    for (double rel = 0.1; rel > 0.002; rel /= 2) {
        fl_mesh a;
        double bound;
        uint32_t level;
        if (fl_hal3_approximate_error(&hal, rel * R, &a, &bound, &level, &err)) {
            std::fprintf(stderr, "%s\n", err.message);
            return 1;
        }
        double ha[2], hq[2];
        hausdorff(&a, &m, ha);
        size_t n = meshopt_simplify(out.data(), idx.data(), idx.size(), pos.data(),
                                    m.vertex_count, 3 * sizeof(float), 3 * a.triangle_count,
                                    1e30f, 0, NULL);
        fl_mesh q = m;
        q.tri = out.data();
        q.triangle_count = n / 3;
        hausdorff(&q, &m, hq);
        std::printf("QEM target=%g ours_tris=%zu ours_bound=%.4f ours_h=%.4f ours_h_in=%.4f "
                    "qem_tris=%zu qem_h=%.4f qem_h_in=%.4f\n",
                    rel, a.triangle_count, bound / R, ha[0] / R, ha[1] / R, n / 3, hq[0] / R,
                    hq[1] / R);
        fl_mesh_free(&a);
    }
    fl_hal3_free(&hal);
    fl_mesh_free(&m);
    return 0;
}

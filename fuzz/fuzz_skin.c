/* Fuzzes the skin surface module on up to 3 decoded balls (grid centres, weights mostly small
 * positive, sometimes zero, negative, NaN or huge) and a shrink factor t: fl_skin_function_new +
 * fl_skin_function_value, fl_balls_union_euler and _betti (chi of the union in [0, positive
 * balls], their count when no two meet; the Betti numbers sum to chi), then fl_skin_mesh with a
 * small cube budget, uniform or graded with local repair (fl_skin_options.repair). Invariants:
 * NaN/Inf, a value beyond 1e100 or no positive weight gives FL_ERR_INPUT, t outside (0, 1)
 * FL_ERR_USAGE; G < 0 at the centre of every ball of positive weight (the centre is inside b^t, so
 * inside the body), G > 0 far outside every ball; on success the mesh is closed, manifold and
 * oriented (fl_mesh_check), outward (positive volume), with finite vertices inside the balls'
 * bounding box, and the measured vertex offset within a grid cell. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    uint8_t head = fz_byte(&in);
    size_t n = fz_byte(&in) % 4; /* <= 3 balls: 4 balls took 2 s an input under ASan */
    static const double ts[8] = {0.5, 0.25, 0.75, 0.1, 0.9, 0.999, 0, 1.5};
    double t = ts[head & 7];
    double xyzw[4 * 6];
    int bad = 0, positive = 0;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < n; i++) {
        bad |= fz_coords(&in, xyzw + 4 * i, 3);
        uint8_t w = fz_byte(&in);
        if (w < 0xe0) xyzw[4 * i + 3] = (double)(1 + (w & 15)) / 4.0 - ((w & 0x10) ? 1.0 : 0.0);
        else xyzw[4 * i + 3] = fz_coord(&in);
        for (int k = 0; k < 4; k++) /* NaN/Inf or beyond the implemented |value| <= 1e100 */
            if (!(fabs(xyzw[4 * i + k]) <= 1e100)) bad = 1;
        if (xyzw[4 * i + 3] > 0) {
            positive = 1;
            double r = sqrt(xyzw[4 * i + 3]);
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], xyzw[4 * i + k] - r);
                hi[k] = fmax(hi[k], xyzw[4 * i + k] + r);
            }
        }
    }
    int usage = !(t > 0 && t < 1);
    fl_error err;
    memset(&err, 0, sizeof err);
    /* fl_balls_union_euler (any t; <= 3 balls always take its auxiliary-ball path): bad values
     * are FL_ERR_INPUT; else chi(union) = components - loops lies in [0, positive balls] (3
     * balls enclose no void), and equals that count when no two positive balls meet. */
    long long chi = -1;
    fl_status est = fl_balls_union_euler(xyzw, n, &chi, &err);
    fz_check_status(est, &err, "fl_balls_union_euler");
    if (bad) {
        FZ_ASSERT(est == FL_ERR_INPUT, "bad balls gave %d for the union's Euler", (int)est);
    } else {
        FZ_ASSERT(est == FL_OK, "union Euler failed (%d): %s", (int)est, err.message);
        long long count = 0;
        int apart = 1;
        for (size_t i = 0; i < n; i++) {
            if (!(xyzw[4 * i + 3] > 0)) continue;
            count++;
            for (size_t j = 0; j < i; j++) {
                if (!(xyzw[4 * j + 3] > 0)) continue;
                double d2 = 0, rr = sqrt(xyzw[4 * i + 3]) + sqrt(xyzw[4 * j + 3]);
                for (int k = 0; k < 3; k++)
                    d2 += (xyzw[4 * i + k] - xyzw[4 * j + k]) * (xyzw[4 * i + k] - xyzw[4 * j + k]);
                if (!(d2 > rr * rr * (1 + 1e-9))) apart = 0;
            }
        }
        FZ_ASSERT(chi >= 0 && chi <= count, "union Euler %lld of %lld balls", chi, count);
        FZ_ASSERT(!apart || chi == count, "union Euler %lld of %lld separate balls", chi, count);
        /* fl_balls_union_betti: the same chi, b0 in [min(count, 1), count], no void (3 balls) */
        long long betti[3] = {-1, -1, -1};
        fl_status bst = fl_balls_union_betti(xyzw, n, betti, &err);
        FZ_ASSERT(bst == FL_OK, "union Betti failed (%d): %s", (int)bst, err.message);
        FZ_ASSERT(betti[0] - betti[1] + betti[2] == chi && betti[1] >= 0 && betti[2] == 0 &&
                      betti[0] <= count && betti[0] >= (count > 0),
                  "union Betti %lld %lld %lld, chi %lld, %lld balls", betti[0], betti[1], betti[2],
                  chi, count);
        FZ_ASSERT(!apart || betti[0] == count, "union b0 %lld of %lld separate balls", betti[0],
                  count);
    }
    fl_skin_function *g = NULL;
    fl_status st = fl_skin_function_new(xyzw, n, t, &g, &err);
    fz_check_status(st, &err, "fl_skin_function_new");
    if (usage) {
        FZ_ASSERT(st == FL_ERR_USAGE, "t = %g gave %d", t, (int)st);
        return 0;
    }
    if (bad || !positive) {
        FZ_ASSERT(st == FL_ERR_INPUT, "bad balls gave %d: %s", (int)st, err.message);
        FZ_ASSERT(g == NULL, "*out not NULL");
        return 0;
    }
    FZ_ASSERT(st == FL_OK, "valid balls rejected (%d): %s", (int)st, err.message);
    double ext = 0;
    for (int k = 0; k < 3; k++) ext = fmax(ext, fmax(fabs(lo[k]), fabs(hi[k])));
    for (size_t i = 0; i < n; i++) {
        if (!(xyzw[4 * i + 3] > 0)) continue;
        double v = fl_skin_function_value(g, xyzw + 4 * i);
        /* G(centre) <= -t w; when t w underflows (a subnormal weight) only G <= 0 is
         * representable */
        if (t * xyzw[4 * i + 3] > 0)
            FZ_ASSERT(v < 0, "G(centre of ball %zu) = %.17g, not inside", i, v);
        else
            FZ_ASSERT(v <= 0, "G(centre of ball %zu) = %.17g, outside", i, v);
    }
    if (isfinite(4 * ext)) {
        double far[3] = {4 * ext + 1, -3 * ext - 1, 2 * ext + 1};
        double v = fl_skin_function_value(g, far);
        FZ_ASSERT(v > 0, "G far outside = %.17g", v);
    }
    fl_skin_function_free(g);

    fl_skin_options o = {0};
    o.t = t;
    o.max_cubes = 1000; /* keeps one input well under a second under ASan */
    /* A coarse grid (a few hundred cubes a ball) so that most inputs get a mesh; the default
     * spacing often exceeds the cube budget kept small for speed. */
    double wmax = 0;
    for (size_t i = 0; i < n; i++) wmax = fmax(wmax, xyzw[4 * i + 3]);
    if (head & 8) o.cell = (double)(1 + fz_byte(&in) % 8) / 8.0;
    else o.cell = sqrt(t * wmax) / (1 + fz_byte(&in) % 3);
    if (head & 16) { /* the graded grid, with its local repair (skin_defects.c) */
        uint8_t gb = fz_byte(&in);
        o.grade = 0.75 * (1 + gb % 4);
        o.repair = 1 + (gb >> 2) % 2;
    }
    fl_mesh m;
    fl_skin_stats stats;
    st = fl_skin_mesh(xyzw, n, &o, &m, &stats, &err);
    fz_check_status(st, &err, "fl_skin_mesh");
    if (st != FL_OK) {
        /* Only the grid budget may refuse valid balls. */
        FZ_ASSERT(st == FL_ERR_INPUT, "skin mesh failed (%d): %s", (int)st, err.message);
        FZ_ASSERT(m.xyz == NULL && m.vertex_count == 0, "*out not zeroed");
        return 0;
    }
    FZ_ASSERT(m.triangle_count > 0, "empty skin mesh");
    double cell = stats.cell;
    for (size_t i = 0; i < m.vertex_count; i++)
        for (int k = 0; k < 3; k++) {
            double x = m.xyz[3 * i + k];
            FZ_ASSERT(isfinite(x), "vertex %zu not finite", i);
            FZ_ASSERT(x >= lo[k] - 1e-9 * ext && x <= hi[k] + 1e-9 * ext,
                      "vertex %zu outside the balls' box", i);
        }
    FZ_ASSERT(stats.max_vertex_offset <= cell, "vertex offset %.3g > cell %.3g",
              stats.max_vertex_offset, cell);
    fl_mesh_check_options co = {.skip_self_intersections = 1};
    fl_mesh_report rep;
    st = fl_mesh_check(&m, &co, &rep, &err);
    FZ_ASSERT(st == FL_OK, "fl_mesh_check failed: %s", err.message);
    FZ_ASSERT(rep.closed && rep.manifold && rep.oriented,
              "skin mesh not a closed oriented manifold: %zu boundary, %zu non-manifold edges, "
              "%zu non-manifold vertices, %zu misoriented",
              rep.boundary_edges, rep.nonmanifold_edges, rep.nonmanifold_vertices,
              rep.misoriented_edges);
    /* The floating-point volume underflows / overflows at extreme scales. */
    FZ_ASSERT(rep.volume > 0 || !(ext > 1e-90 && ext < 1e90), "skin mesh not outward (volume %.3g)",
              rep.volume);
    fl_mesh_report_free(&rep);
    fl_mesh_free(&m);
    return 0;
}

/* Fuzzes fl_hal2_build + fl_hal2_contains + fl_hal2_approximate_level on up to 3 decoded rings of
 * 3..16 vertices (repeated, collinear and self-intersecting rings included). Oracle: every
 * contains answer equals the brute-force even-odd test with exact predicates
 * (tests/hal/hal2_oracle.h); the approximation's certified error bounds the distance of every
 * original vertex to it (checked when coordinates are moderate, so the floating-point distance
 * is meaningful). */
#include "fuzz_common.h"
#include "hal/hal2_oracle.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    uint8_t head = fz_byte(&in);
    size_t rings = 1 + head % 3;
    double xy[2 * 48];
    size_t ring_start[4], polygon_start[4], polygons = 0, nv = 0;
    int bad = 0;
    for (size_t r = 0; r < rings; r++) {
        size_t len = (size_t)(fz_byte(&in) % 17); /* 0..2 give a clean FL_ERR_INPUT */
        ring_start[r] = nv;
        /* Ring r > 0 is a hole of the previous polygon when bit r of head is set. */
        if (r == 0 || !(head & (8u << r))) polygon_start[polygons++] = r;
        bad |= fz_coords(&in, xy + 2 * nv, 2 * len);
        nv += len;
    }
    ring_start[rings] = nv;
    polygon_start[polygons] = rings;
    fl_polygon poly = {nv, xy, rings, ring_start, polygons, polygon_start};
    int short_ring = 0;
    for (size_t r = 0; r < rings; r++) short_ring |= ring_start[r + 1] - ring_start[r] < 3;
    fl_hal2 hal;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_hal2_build(&poly, NULL, &hal, &err);
    fz_check_status(st, &err, "fl_hal2_build");
    if (st != FL_OK) {
        FZ_ASSERT(st == FL_ERR_INPUT, "build gave %d: %s", (int)st, err.message);
        FZ_ASSERT(bad || short_ring, "valid polygon rejected: %s", err.message);
        return 0;
    }
    FZ_ASSERT(!bad && !short_ring, "NaN/Inf or short ring accepted");
    /* Queries: decoded points, every vertex and every edge midpoint. */
    double q[2 * (16 + 2 * 48)];
    size_t nq = fz_byte(&in) % 17;
    int qbad = fz_coords(&in, q, 2 * nq);
    for (size_t v = 0; v < nv; v++) {
        size_t w = v + 1;
        for (size_t r = 0; r < rings; r++)
            if (w == ring_start[r + 1]) w = ring_start[r];
        q[2 * nq] = xy[2 * v], q[2 * nq + 1] = xy[2 * v + 1], nq++;
        q[2 * nq] = xy[2 * v] / 2 + xy[2 * w] / 2;
        q[2 * nq + 1] = xy[2 * v + 1] / 2 + xy[2 * w + 1] / 2;
        nq++;
    }
    uint8_t where[16 + 2 * 48];
    st = fl_hal2_contains(&hal, q, nq, where, &err);
    fz_check_status(st, &err, "fl_hal2_contains");
    if (qbad) {
        FZ_ASSERT(st == FL_ERR_INPUT, "NaN/Inf query gave %d", (int)st);
    } else {
        FZ_ASSERT(st == FL_OK, "contains failed: %s", err.message);
        for (size_t k = 0; k < nq; k++)
            FZ_ASSERT(where[k] == oracle_where(&poly, q + 2 * k), "query %zu (%.17g, %.17g): "
                      "hal %d, brute force %d", k, q[2 * k], q[2 * k + 1], where[k],
                      oracle_where(&poly, q + 2 * k));
    }
    double maxabs = 0;
    for (size_t i = 0; i < 2 * nv; i++) maxabs = fmax(maxabs, fabs(xy[i]));
    fl_polygon approx;
    double bound;
    uint32_t level = fz_byte(&in) % (hal.depth + 2);
    st = fl_hal2_approximate_level(&hal, level, &approx, &bound, &err);
    fz_check_status(st, &err, "fl_hal2_approximate_level");
    FZ_ASSERT(st == FL_OK, "approximate_level failed: %s", err.message);
    if (maxabs < 1e100 && maxabs > 1e-100) {
        double dev = oracle_deviation(&poly, &approx);
        FZ_ASSERT(dev <= bound * (1 + 1e-9) + 1e-12 * maxabs, "level %u deviation %.17g > "
                  "certified %.17g", level, dev, bound);
    }
    fl_polygon_free(&approx);
    fl_hal2_free(&hal);
    return 0;
}

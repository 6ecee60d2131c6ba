/* Fuzzes fl_dt2_build, fl_dt3_build and fl_rt3_build on up to 64 decoded points: the first byte
 * picks the triangulation. Invariants: NaN/Inf input is FL_ERR_INPUT; finite input never gives
 * FL_ERR_ALGORITHM unless all points are collinear/coplanar (checked exactly); on success the
 * independent verifier (fl_*_verify) accepts the result. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    int which = fz_byte(&in) % 3;
    size_t n = fz_byte(&in) % 65;
    int dim = which == 0 ? 2 : which == 1 ? 3 : 4;
    double c[64 * 4];
    int bad = fz_coords(&in, c, n * (size_t)dim);
    if (which == 2) { /* weights: keep them moderate most of the time, NaN stays NaN */
        bad = 0;
        for (size_t i = 0; i < 4 * n; i++) {
            if (i % 4 == 3 && fabs(c[i]) > 1e3 && !(c[i - 1] == 0)) c[i] = 1;
            bad |= !isfinite(c[i]);
        }
    }
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st, vst;
    if (which == 0) {
        fl_dt2 dt;
        fl_dt2_options opt = {0};
        opt.want_circumcenters = (int)(n & 1);
        st = fl_dt2_build(c, n, &opt, &dt, &err);
        fz_check_status(st, &err, "fl_dt2_build");
        if (st != FL_OK) goto failed;
        vst = fl_dt2_verify(c, &dt, &err);
        FZ_ASSERT(vst == FL_OK, "fl_dt2_verify: %s", err.message);
        fl_dt2_free(&dt);
    } else if (which == 1) {
        fl_dt3 dt;
        fl_dt3_options opt = {0};
        opt.want_circumcenters = (int)(n & 1);
        st = fl_dt3_build(c, n, &opt, &dt, &err);
        fz_check_status(st, &err, "fl_dt3_build");
        if (st != FL_OK) goto failed;
        vst = fl_dt3_verify(c, &dt, &err);
        FZ_ASSERT(vst == FL_OK, "fl_dt3_verify: %s", err.message);
        fl_dt3_free(&dt);
    } else {
        fl_rt3 rt;
        fl_rt3_options opt = {0};
        opt.want_ortho = (int)(n & 1);
        st = fl_rt3_build(c, n, &opt, &rt, &err);
        fz_check_status(st, &err, "fl_rt3_build");
        if (st != FL_OK) goto failed;
        vst = fl_rt3_verify(c, &rt, &err);
        FZ_ASSERT(vst == FL_OK, "fl_rt3_verify: %s", err.message);
        fl_rt3_free(&rt);
    }
    FZ_ASSERT(!bad, "NaN/Inf input accepted");
    return 0;
failed:
    if (bad) FZ_ASSERT(st == FL_ERR_INPUT, "NaN/Inf input gave %d: %s", (int)st, err.message);
    /* Documented: FL_ERR_ALGORITHM only when all points are collinear (2D) / coplanar (3D). */
    if (st == FL_ERR_ALGORITHM)
        FZ_ASSERT(which == 0 ? fz_collinear2(c, n) : fz_coplanar3(c, n, (size_t)dim),
                  "FL_ERR_ALGORITHM on full-dimensional input: %s", err.message);
    return 0;
}

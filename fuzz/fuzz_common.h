/* Shared helpers of the libFuzzer targets: a byte decoder that turns the fuzz input into a small
 * bounded geometric input, and the invariants every public call must keep (a status in range,
 * a non-empty message on failure, NaN/Inf rejected with FL_ERR_INPUT). A broken invariant calls
 * abort() so libFuzzer records the input as a crash. */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "flintstone.h"

#define FZ_ASSERT(cond, ...)                                                                       \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            fprintf(stderr, "%s:%d: invariant broken: %s: ", __FILE__, __LINE__, #cond);          \
            fprintf(stderr, __VA_ARGS__);                                                          \
            fputc('\n', stderr);                                                                   \
            abort();                                                                               \
        }                                                                                          \
    } while (0)

/* A failing call must say why: status in 1..5, err.status equal to it, a non-empty message. */
static inline void fz_check_status(fl_status st, const fl_error *err, const char *call)
{
    FZ_ASSERT(st >= FL_OK && st <= FL_ERR_NOMEM, "%s returned %d", call, (int)st);
    if (st == FL_OK) return;
    FZ_ASSERT(err->status == st, "%s: err.status %d != %d", call, (int)err->status, (int)st);
    FZ_ASSERT(err->message[0] != '\0', "%s failed (%d) with an empty message", call, (int)st);
    FZ_ASSERT(memchr(err->message, 0, sizeof err->message) != NULL, "%s: unterminated", call);
}

/* Decoder over the fuzz bytes; reads past the end give zeros. */
typedef struct fz_in {
    const uint8_t *d;
    size_t n, pos;
} fz_in;

static inline uint8_t fz_byte(fz_in *in) { return in->pos < in->n ? in->d[in->pos++] : 0; }

static inline size_t fz_left(const fz_in *in) { return in->n - in->pos; }

/* A coordinate: mostly small grid values (so that degeneracies - duplicates, collinear and
 * cocircular points - are common), sometimes a raw double, a scaled value or a special one. */
static inline double fz_coord(fz_in *in)
{
    uint8_t b = fz_byte(in);
    switch (b >> 5) {
    case 0:
    case 1:
    case 2:
    case 3: return (double)((int)(b & 0x7f) - 64) / 8.0; /* grid of step 1/8 */
    case 4: return (double)((int)(b & 31) - 16);         /* integer grid */
    case 5: {                                             /* raw double (incl. NaN/Inf) */
        double v;
        uint8_t raw[8];
        for (int i = 0; i < 8; i++) raw[i] = fz_byte(in);
        memcpy(&v, raw, 8);
        return v;
    }
    case 6: { /* huge / tiny scales */
        static const double scale[8] = {1e300, -1e300, 1e-300, -1e-300, 1e150, 1e-150, 0x1p-1074,
                                        1.0 + 0x1p-52};
        return scale[b & 7] * (double)(1 + ((b >> 3) & 3));
    }
    default: { /* specials */
        static const double sp[8] = {0.0, -0.0, 1e308, -1e308, 0.5, 1.0 / 3.0, 0, 0};
        int k = b & 7;
        if (k == 6) return NAN;
        if (k == 7) return (b & 8) ? INFINITY : -INFINITY;
        return sp[k];
    }
    }
}

/* Fills `count` coordinates; returns 1 when any of them is NaN or infinite. */
static inline int fz_coords(fz_in *in, double *out, size_t count)
{
    int bad = 0;
    for (size_t i = 0; i < count; i++) {
        out[i] = fz_coord(in);
        if (!isfinite(out[i])) bad = 1;
    }
    return bad;
}

/* Exactly (fl_orient2d) whether all n points xy lie on one line (or coincide). */
static inline int fz_collinear2(const double *xy, size_t n)
{
    size_t b = n;
    for (size_t i = 1; i < n && b == n; i++)
        if (xy[2 * i] != xy[0] || xy[2 * i + 1] != xy[1]) b = i;
    for (size_t i = 0; b < n && i < n; i++)
        if (fl_orient2d(xy, xy + 2 * b, xy + 2 * i) != 0) return 0;
    return 1;
}

/* Exactly whether points a, b, c of R^3 are collinear: all three coordinate projections are. */
static inline int fz_collinear3(const double *a, const double *b, const double *c)
{
    for (int k = 0; k < 3; k++) {
        int i = k, j = (k + 1) % 3;
        double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
        if (fl_orient2d(pa, pb, pc) != 0) return 0;
    }
    return 1;
}

/* Exactly whether all n points (stride doubles apart, xyz first) lie in one plane. */
static inline int fz_coplanar3(const double *p, size_t n, size_t stride)
{
    size_t b = n, c = n;
    for (size_t i = 1; i < n && b == n; i++)
        if (p[stride * i] != p[0] || p[stride * i + 1] != p[1] || p[stride * i + 2] != p[2])
            b = i;
    for (size_t i = b + 1; b < n && i < n && c == n; i++)
        if (!fz_collinear3(p, p + stride * b, p + stride * i)) c = i;
    if (c == n) return 1;
    for (size_t i = 0; i < n; i++)
        if (fl_orient3d(p, p + stride * b, p + stride * c, p + stride * i) != 0) return 0;
    return 1;
}

/* A small closed oriented genus-0 mesh decoded from the bytes: a tetrahedron, an octahedron, or
 * an octahedron with some faces replaced by three triangles to an apex pushed outward (up to 14
 * vertices, 24 triangles; xyz and tri must hold that much). Every vertex is scaled and moved by
 * a decoded offset (fz_coord / 16: mostly small, sometimes NaN/Inf/huge, so folds, near-flat
 * spots and bad coordinates all occur). With `mutate`, one byte may then flip a triangle or
 * redirect a corner (open, misoriented or non-manifold input). The caller judges validity. */
static inline void fz_closed_mesh(fz_in *in, int mutate, double *xyz, uint32_t *tri, size_t *nv,
                                  size_t *nt)
{
    static const double scale[8] = {1, 1, 1, 1e-3, 1e3, 1e-100, 1e100, 0.125};
    uint8_t shape = fz_byte(in), split = 0;
    double s = scale[(shape >> 2) & 7];
    if ((shape & 3) == 0) { /* tetrahedron */
        static const double v[12] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4};
        static const uint32_t t[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
        memcpy(xyz, v, sizeof v), memcpy(tri, t, sizeof t);
        *nv = 4, *nt = 4;
    } else { /* octahedron: vertices +x -x +y -y +z -z */
        for (int i = 0; i < 18; i++) xyz[i] = 0;
        for (int i = 0; i < 6; i++) xyz[3 * i + i / 2] = (i & 1) ? -4 : 4;
        *nv = 6, *nt = 0;
        split = (shape & 3) == 1 ? 0 : fz_byte(in);
        for (uint32_t f = 0; f < 8; f++) {
            uint32_t a = f & 1, b = 2 + ((f >> 1) & 1), c = 4 + ((f >> 2) & 1);
            if ((a + b + c) & 1) { /* odd number of negative axes: swap to stay outward */
                uint32_t x = b;
                b = c, c = x;
            }
            if (!((split >> f) & 1)) {
                tri[3 * *nt] = a, tri[3 * *nt + 1] = b, tri[3 * *nt + 2] = c, ++*nt;
                continue;
            }
            uint32_t q = (uint32_t)(*nv)++;
            for (int k = 0; k < 3; k++) /* apex at twice the face centroid */
                xyz[3 * q + k] = 2.0 * (xyz[3 * a + k] + xyz[3 * b + k] + xyz[3 * c + k]) / 3.0;
            uint32_t e[3][3] = {{a, b, q}, {b, c, q}, {c, a, q}};
            for (int k = 0; k < 3; k++, ++*nt) memcpy(tri + 3 * *nt, e[k], sizeof e[k]);
        }
    }
    for (size_t i = 0; i < 3 * *nv; i++) xyz[i] = s * (xyz[i] + fz_coord(in) / 16.0);
    if (!mutate) return;
    uint8_t m = fz_byte(in);
    size_t t = (size_t)(m >> 2) % *nt;
    if ((m & 3) == 1) { /* flip */
        uint32_t x = tri[3 * t];
        tri[3 * t] = tri[3 * t + 1], tri[3 * t + 1] = x;
    } else if ((m & 3) == 2) { /* redirect a corner */
        tri[3 * t + (m >> 6) % 3] = (uint32_t)(fz_byte(in) % *nv);
    }
}

/* Exactly what libFuzzer calls; declared here to satisfy -Wmissing-prototypes. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#endif

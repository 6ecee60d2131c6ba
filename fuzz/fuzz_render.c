/* Fuzzes src/render on decoded scenes. SVG canvas: up to 6 items (points, polylines, a polygon,
 * edges, discs, lenses, disc-and-half-plane parts, Bézier paths) with decoded coordinates, then
 * fl_svg_write; raster: a tiny image (<= 40 x 40, any camera) of a mesh of any topology (with
 * normals / scalars / wireframe / zebra), balls and points. Invariants: non-finite coordinates and
 * negative radii give FL_ERR_INPUT, valid items are accepted; the written SVG is one <svg>
 * element with as many shape elements as fl_svg_element_count says and no "nan" or "inf" in
 * its text; the raster has the asked size, covers at most every pixel, has a finite camera,
 * and projects every finite scene point to finite pixel coordinates. */
#include <unistd.h>

#include "fuzz_common.h"

static int all_finite(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

static void expect(fl_status st, const fl_error *err, int bad, const char *call)
{
    fz_check_status(st, err, call);
    if (bad) FZ_ASSERT(st == FL_ERR_INPUT, "%s: bad input gave %d", call, (int)st);
    else FZ_ASSERT(st == FL_OK, "%s: valid input gave %d: %s", call, (int)st, err->message);
}

/* The disc's box is representable (the canvas rejects discs beyond the double range). */
static int disc_ok(double x, double y, double r)
{
    return isfinite(x - r) && isfinite(x + r) && isfinite(y - r) && isfinite(y + r);
}

static size_t count_of(const char *text, const char *what)
{
    size_t c = 0;
    for (const char *p = strstr(text, what); p; p = strstr(p + 1, what)) c++;
    return c;
}

static void fuzz_svg(fz_in *in)
{
    fl_svg *svg = NULL;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_svg_new(fz_byte(in) & 1 ? 100 : 0, &svg, &err);
    FZ_ASSERT(st == FL_OK, "fl_svg_new: %s", err.message);
    size_t items = 1 + fz_byte(in) % 6;
    fl_svg_style style = {0};
    for (size_t it = 0; it < items; it++) {
        uint8_t kind = fz_byte(in);
        double v[2 * 7];
        size_t n = 1 + (kind >> 3) % 7;
        int bad = fz_coords(in, v, 2 * n);
        switch (kind & 7) {
        case 0: st = fl_svg_add_points(svg, v, n, &style, &err); break;
        case 1: st = fl_svg_add_polyline(svg, v, n, kind >> 7, &style, &err); break;
        case 2: {
            size_t rs[2] = {0, n}, ps[2] = {0, 1};
            fl_polygon pg = {n, v, 1, rs, 1, ps};
            st = fl_svg_add_polygon(svg, &pg, &style, &err);
            break;
        }
        case 3: {
            uint32_t e[4] = {0, (uint32_t)(n - 1), (uint32_t)(n / 2), 0};
            bad = 0; /* only the points the edges use */
            for (int k = 0; k < 4; k++)
                bad |= !isfinite(v[2 * e[k]]) || !isfinite(v[2 * e[k] + 1]);
            st = fl_svg_add_edges(svg, v, n, e, 2, &style, &err);
            break;
        }
        case 4: { /* uses the centre and the radius only */
            double r = n > 1 ? v[2 * n - 1] : 0;
            bad = !isfinite(v[0]) || !isfinite(v[1]) || !isfinite(r) || !(r >= 0) ||
                  !disc_ok(v[0], v[1], r);
            st = fl_svg_add_disc(svg, v[0], v[1], r, &style, &err);
            break;
        }
        case 5: {
            bad = !isfinite(v[0]) || !isfinite(v[1]) || !isfinite(v[2 * n - 1]) ||
                  !disc_ok(v[0], v[1], fabs(v[2 * n - 1])) || !disc_ok(v[1], v[0], 1.5);
            double d0[3] = {v[0], v[1], fabs(v[2 * n - 1])}, d1[3] = {v[1], v[0], 1.5};
            st = fl_svg_add_lens(svg, d0, d1, &style, &err);
            break;
        }
        case 6: {
            double disc[3] = {v[0], v[1], fabs(v[2 * n - 1])}, a[2] = {v[1], v[0]},
                   b[2] = {v[0] + 1, v[1]};
            bad = !isfinite(v[0]) || !isfinite(v[1]) || !isfinite(v[2 * n - 1]) ||
                  !disc_ok(v[0], v[1], fabs(v[2 * n - 1])) || !isfinite(b[0]) ||
                  (a[0] == b[0] && a[1] == b[1]);
            st = fl_svg_add_disc_halfplane(svg, disc, a, b, (kind & 0x80) ? 1 : -1, &style, &err);
            break;
        }
        default:
            if (n < 4) { /* one cubic segment needs 4 control points */
                fz_coords(in, v + 2 * n, 8 - 2 * n);
                n = 4;
                bad = !all_finite(v, 8);
            }
            bad = !all_finite(v, 2 * (3 * ((n - 1) / 3) + 1)); /* the control points used */
            st = fl_svg_add_bezier(svg, v, (n - 1) / 3, &style, &err);
            break;
        }
        expect(st, &err, bad, "fl_svg_add_*");
    }
    char path[64];
    snprintf(path, sizeof path, "/tmp/fuzz_render_%ld.svg", (long)getpid());
    st = fl_svg_write(svg, path, &err);
    FZ_ASSERT(st == FL_OK, "fl_svg_write: %s", err.message);
    FILE *f = fopen(path, "rb");
    FZ_ASSERT(f != NULL, "written file missing");
    static char text[1 << 20];
    size_t len = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    remove(path);
    text[len] = 0;
    for (size_t i = 0; i < len; i++) text[i] = (char)(text[i] >= 'A' && text[i] <= 'Z'
                                                           ? text[i] + 32 : text[i]);
    FZ_ASSERT(!strstr(text, "nan") && !strstr(text, "inf"), "non-finite number in the SVG:\n%s",
              text);
    FZ_ASSERT(count_of(text, "<svg") == 1 && count_of(text, "</svg>") == 1, "not one <svg>");
    size_t shapes = count_of(text, "<circle") + count_of(text, "<path");
    FZ_ASSERT(shapes >= fl_svg_element_count(svg), "%zu shapes written, %zu counted", shapes,
              fl_svg_element_count(svg));
    double w, h;
    fl_svg_size(svg, &w, &h);
    FZ_ASSERT(isfinite(w) && isfinite(h) && w > 0 && h > 0, "picture size %g x %g", w, h);
    fl_svg_free(svg);
}

static void fuzz_raster(fz_in *in)
{
    uint8_t a = fz_byte(in), b = fz_byte(in);
    fl_render_options o = {0};
    o.width = 1 + a % 40;
    o.height = 1 + b % 40;
    o.orthographic = a >> 7;
    o.supersample = (b >> 7) ? 2 : 1;
    o.azimuth = (double)fz_byte(in) * 7.3 - 900;
    o.elevation = (double)((int)fz_byte(in) - 128) * 0.75;
    fl_render *r = NULL;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_render_new(&o, &r, &err);
    FZ_ASSERT(st == FL_OK, "fl_render_new: %s", err.message);
    double xyz[3 * 6], nrm[3 * 6], sc[6], balls[4 * 3], pts[3 * 3];
    uint32_t tri[3 * 4];
    int any = 0; /* something with an extent was accepted */
    size_t nv = 1 + fz_byte(in) % 6, nt = fz_byte(in) % 5;
    int bad = fz_coords(in, xyz, 3 * nv);
    for (size_t i = 0; i < 3 * nt; i++) tri[i] = fz_byte(in) % nv;
    uint8_t sb = fz_byte(in);
    fl_render_mesh_style style = {0};
    if (sb & 1) {
        bad |= fz_coords(in, nrm, 3 * nv);
        style.normals = nrm;
    }
    if (sb & 2) {
        bad |= fz_coords(in, sc, nv);
        style.scalars = sc;
        style.colormap = (sb >> 2) % 3;
    }
    style.wireframe = (sb >> 4) & 1;
    style.zebra = (sb >> 5) & 1;
    fl_mesh m = {nv, xyz, nt, tri};
    st = fl_render_add_mesh(r, &m, &style, &err);
    expect(st, &err, bad, "fl_render_add_mesh");
    double lo = INFINITY, hi = -INFINITY;
    if (st == FL_OK && nt) {
        for (size_t i = 0; i < 3 * nt; i++)
            for (int k = 0; k < 3; k++) {
                lo = fmin(lo, xyz[3 * tri[i] + k]);
                hi = fmax(hi, xyz[3 * tri[i] + k]);
            }
        any |= hi > lo;
    }
    size_t nb = fz_byte(in) % 4;
    bad = fz_coords(in, balls, 4 * nb);
    fl_balls bl = {nb, balls};
    st = fl_render_add_balls(r, &bl, NULL, &err);
    expect(st, &err, bad, "fl_render_add_balls");
    for (size_t i = 0; st == FL_OK && i < nb; i++) any |= balls[4 * i + 3] > 0;
    size_t np = fz_byte(in) % 4;
    bad = fz_coords(in, pts, 3 * np);
    st = fl_render_add_points(r, pts, np, 0, NULL, &err);
    expect(st, &err, bad, "fl_render_add_points");
    any |= st == FL_OK && np > 0;
    fl_image img;
    fl_render_stats stats;
    st = fl_render_finish(r, &img, &stats, &err);
    fz_check_status(st, &err, "fl_render_finish");
    if (st == FL_OK) {
        FZ_ASSERT(img.width == o.width && img.height == o.height && img.rgba, "image size");
        FZ_ASSERT(stats.pixels_covered <= (size_t)o.width * o.height, "covered");
        const fl_render_camera *c = &stats.camera;
        FZ_ASSERT(all_finite(c->center, 3) && all_finite(c->right, 3) && all_finite(c->up, 3) &&
                      all_finite(c->toward, 3) && isfinite(c->scale) && all_finite(c->offset, 2),
                  "camera not finite");
        /* every value of the scene within 1e150: the used vertices project to finite points */
        double big = 0;
        for (size_t i = 0; i < 4 * nb; i++) big = fmax(big, fabs(balls[i]));
        for (size_t i = 0; i < 3 * np; i++) big = fmax(big, fabs(pts[i]));
        for (size_t i = 0; i < 3 * nt && big < 1e150 && fabs(hi) < 1e150 && fabs(lo) < 1e150;
             i++) {
            double p[3];
            fl_render_project(c, xyz + 3 * tri[i], p);
            FZ_ASSERT(all_finite(p, 3), "vertex %u projects to a non-finite point", tri[i]);
        }
    } else {
        FZ_ASSERT(st == FL_ERR_INPUT || st == FL_ERR_NOMEM, "finish gave %d: %s", (int)st,
                  err.message);
        FZ_ASSERT(img.rgba == NULL, "image not zeroed");
        (void)any;
    }
    fl_image_free(&img);
    fl_render_free(r);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    if (fz_byte(&in) & 1) fuzz_raster(&in);
    else fuzz_svg(&in);
    return 0;
}

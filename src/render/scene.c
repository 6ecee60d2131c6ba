/* The scene: what fl_render_add_* collected (validated copies) and fl_render_finish, which fits
 * the camera to it, rasterizes into a sample buffer and averages samples into pixels. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"

#define MAX_SIDE 16384u

static const uint8_t default_mesh_color[4] = {176, 196, 222, 255}; /* light steel blue */
static const uint8_t default_ball_color[4] = {235, 140, 52, 255};
static const uint8_t default_point_color[4] = {70, 70, 70, 255};

void fl_image_free(fl_image *image)
{
    if (!image) return;
    free(image->rgba);
    memset(image, 0, sizeof *image);
}

fl_status fl_render_new(const fl_render_options *opt, fl_render **out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_render_new: NULL argument");
    *out = NULL;
    fl_render_options o = {0};
    if (opt) o = *opt;
    if (o.width == 0 && o.height == 0) {
        o.width = 800;
        o.height = 600;
    }
    if (o.width == 0 || o.height == 0 || o.width > MAX_SIDE || o.height > MAX_SIDE)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "render: size %ux%u is not in 1..%u", o.width,
                       o.height, MAX_SIDE);
    if (o.fov == 0) o.fov = 30;
    if (!(o.fov > 0 && o.fov < 170))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "render: field of view must be in (0, 170)");
    if (o.supersample == 0) o.supersample = 1;
    if (o.supersample != 1 && o.supersample != 2)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "render: supersample must be 1 or 2");
    /* The sample buffer costs 11 bytes a sample; 2^26 samples (8192^2, or 4096^2 at 2x2) keep
     * it under a gigabyte. */
    if ((double)o.width * o.height * o.supersample * o.supersample > (double)(1u << 26))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "render: %ux%u with %dx%d samples a pixel is more than 2^26 samples",
                       o.width, o.height, o.supersample, o.supersample);
    if (o.margin == 0) o.margin = 0.05;
    if (!(o.margin > 0 && o.margin < 0.45))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "render: margin must be in (0, 0.45)");
    if (!isfinite(o.azimuth) || !isfinite(o.elevation))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "render: view angles must be finite");
    fl_render *r = calloc(1, sizeof *r);
    if (!r) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    r->opt = o;
    static const uint8_t white[4] = {255, 255, 255, 255};
    memcpy(r->background, o.background ? o.background : white, 4);
    r->opt.background = NULL; /* the caller's buffer need not outlive this call */
    fl_vec_init(&r->meshes, sizeof(render_mesh));
    fl_vec_init(&r->spheres, sizeof(render_sphere));
    *out = r;
    return FL_OK;
}

static void mesh_release(render_mesh *m)
{
    free(m->xyz);
    free(m->tri);
    free(m->normals);
    free(m->rgb);
}

void fl_render_free(fl_render *render)
{
    if (!render) return;
    render_mesh *m = render->meshes.data;
    for (size_t i = 0; i < render->meshes.count; i++)
        mesh_release(&m[i]);
    fl_vec_free(&render->meshes);
    fl_vec_free(&render->spheres);
    free(render);
}

static int all_finite(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

/* Per-vertex colours: the base colour, or the scalars through the colormap. */
static void vertex_colors(const fl_mesh *mesh, const fl_render_mesh_style *st, uint8_t *rgb)
{
    const uint8_t *base = st->color ? st->color : default_mesh_color;
    double lo = st->scalar_min, hi = st->scalar_max;
    if (st->scalars && !(lo < hi)) {
        lo = INFINITY;
        hi = -INFINITY;
        for (size_t i = 0; i < mesh->vertex_count; i++) {
            lo = fmin(lo, st->scalars[i]);
            hi = fmax(hi, st->scalars[i]);
        }
    }
    for (size_t i = 0; i < mesh->vertex_count; i++) {
        uint8_t c[4];
        if (st->scalars)
            fl_render_colormap_rgba(st->colormap, hi > lo ? (st->scalars[i] - lo) / (hi - lo) : 0.5,
                                    c);
        else
            memcpy(c, base, 4);
        memcpy(rgb + 3 * i, c, 3);
    }
}

static fl_status check_mesh(const fl_mesh *mesh, const fl_render_mesh_style *st, fl_error *err)
{
    if (!mesh || (mesh->vertex_count && !mesh->xyz) || (mesh->triangle_count && !mesh->tri))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_render_add_mesh: NULL argument");
    if (mesh->vertex_count > SIZE_MAX / 3 || mesh->triangle_count > SIZE_MAX / 3)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "render: mesh too large");
    if (!all_finite(mesh->xyz, 3 * mesh->vertex_count))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "render: mesh has a non-finite coordinate");
    if (st->normals && !all_finite(st->normals, 3 * mesh->vertex_count))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "render: non-finite vertex normal");
    if (st->scalars && !all_finite(st->scalars, mesh->vertex_count))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "render: non-finite vertex scalar");
    if (st->zebra_stripes < 0 || !isfinite(st->zebra_stripes))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "render: zebra_stripes must be >= 0");
    if ((unsigned)st->colormap > FL_RENDER_GRAY)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "render: unknown colormap %d",
                       (int)st->colormap);
    for (size_t i = 0; i < 3 * mesh->triangle_count; i++)
        if (mesh->tri[i] >= mesh->vertex_count)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "render: triangle %zu uses vertex %u but there are %zu", i / 3,
                           mesh->tri[i], mesh->vertex_count);
    return FL_OK;
}

fl_status fl_render_add_mesh(fl_render *render, const fl_mesh *mesh,
                             const fl_render_mesh_style *style, fl_error *err)
{
    fl_render_mesh_style st = {0};
    if (style) st = *style;
    if (!render) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_render_add_mesh: NULL render");
    fl_status s = check_mesh(mesh, &st, err);
    if (s) return s;
    render_mesh m = {0};
    m.vertex_count = mesh->vertex_count;
    m.triangle_count = mesh->triangle_count;
    m.wireframe = st.wireframe;
    m.zebra = st.zebra;
    m.zebra_stripes = st.zebra_stripes > 0 ? st.zebra_stripes : 10;
    size_t nv = mesh->vertex_count ? mesh->vertex_count : 1;
    m.xyz = fl_alloc_array(nv, 3 * sizeof(double));
    m.tri = fl_alloc_array(mesh->triangle_count ? mesh->triangle_count : 1, 3 * sizeof(uint32_t));
    m.rgb = fl_alloc_array(nv, 3);
    m.normals = st.normals ? fl_alloc_array(nv, 3 * sizeof(double)) : NULL;
    if (!m.xyz || !m.tri || !m.rgb || (st.normals && !m.normals) ||
        fl_vec_reserve(&render->meshes, render->meshes.count + 1)) {
        mesh_release(&m);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    memcpy(m.xyz, mesh->xyz, mesh->vertex_count * 3 * sizeof(double));
    memcpy(m.tri, mesh->tri, mesh->triangle_count * 3 * sizeof(uint32_t));
    if (st.normals) memcpy(m.normals, st.normals, mesh->vertex_count * 3 * sizeof(double));
    vertex_colors(mesh, &st, m.rgb);
    fl_vec_push(&render->meshes, &m, 1); /* cannot fail: reserved above */
    return FL_OK;
}

static fl_status push_spheres(fl_render *render, const double *v, size_t n, size_t stride,
                              double radius, const uint8_t *color, fl_error *err)
{
    if (fl_vec_reserve(&render->spheres, render->spheres.count + n))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    for (size_t i = 0; i < n; i++) {
        const double *b = v + stride * i;
        render_sphere s = {{b[0], b[1], b[2]}, stride == 4 ? sqrt(b[3]) : radius, {0}};
        if (stride == 4 && !(b[3] > 0)) continue;
        memcpy(s.rgb, color, 3);
        fl_vec_push(&render->spheres, &s, 1);
    }
    return FL_OK;
}

fl_status fl_render_add_balls(fl_render *render, const fl_balls *balls, const uint8_t *color,
                              fl_error *err)
{
    if (!render || !balls || (balls->count && !balls->xyzw))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_render_add_balls: NULL argument");
    if (balls->count > SIZE_MAX / 4 || !all_finite(balls->xyzw, 4 * balls->count))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "render: a ball has a non-finite value");
    return push_spheres(render, balls->xyzw, balls->count, 4, 0, color ? color : default_ball_color,
                        err);
}

fl_status fl_render_add_points(fl_render *render, const double *xyz, size_t n, double radius,
                               const uint8_t *color, fl_error *err)
{
    if (!render || (n && !xyz))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_render_add_points: NULL argument");
    if (n > SIZE_MAX / 3 || !all_finite(xyz, 3 * n) || !isfinite(radius))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "render: a point has a non-finite value");
    if (!(radius > 0) && n) {
        double lo[3], hi[3];
        for (int k = 0; k < 3; k++)
            lo[k] = hi[k] = xyz[k];
        for (size_t i = 1; i < n; i++)
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], xyz[3 * i + k]);
                hi[k] = fmax(hi[k], xyz[3 * i + k]);
            }
        double d = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                        (hi[2] - lo[2]) * (hi[2] - lo[2]));
        radius = d > 0 ? 0.004 * d : 0.01;
    }
    return push_spheres(render, xyz, n, 3, radius, color ? color : default_point_color, err);
}

static void bbox_add(double bbox[6], const double p[3], double r)
{
    for (int k = 0; k < 3; k++) {
        bbox[k] = fmin(bbox[k], p[k] - r);
        bbox[3 + k] = fmax(bbox[3 + k], p[k] + r);
    }
}

/* The box around every referenced vertex and every sphere; 0 when there is none. */
static int scene_bbox(const fl_render *r, double bbox[6])
{
    for (int k = 0; k < 3; k++) {
        bbox[k] = INFINITY;
        bbox[3 + k] = -INFINITY;
    }
    const render_mesh *m = r->meshes.data;
    for (size_t i = 0; i < r->meshes.count; i++)
        for (size_t t = 0; t < 3 * m[i].triangle_count; t++)
            bbox_add(bbox, m[i].xyz + 3 * (size_t)m[i].tri[t], 0);
    const render_sphere *s = r->spheres.data;
    for (size_t i = 0; i < r->spheres.count; i++)
        bbox_add(bbox, s[i].c, s[i].r);
    return bbox[0] <= bbox[3];
}

static fl_status target_init(render_target *t, const fl_render *r, fl_error *err)
{
    memset(t, 0, sizeof *t);
    uint32_t ss = (uint32_t)r->opt.supersample;
    t->w = r->opt.width * ss;
    t->h = r->opt.height * ss;
    t->ss = (int)ss;
    size_t n = (size_t)t->w * t->h;
    t->rgb = fl_alloc_array(n, 3);
    t->near = fl_alloc_array(n, sizeof(double));
    if (!t->rgb || !t->near) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    for (size_t i = 0; i < n; i++) {
        memcpy(t->rgb + 3 * i, r->background, 3);
        t->near[i] = -INFINITY;
    }
    return FL_OK;
}

/* Averages ss x ss samples into a pixel; a pixel is covered when any of its samples is. */
static size_t resolve(const render_target *t, const fl_render *r, fl_image *img)
{
    uint32_t ss = (uint32_t)r->opt.supersample;
    size_t covered = 0;
    for (uint32_t y = 0; y < img->height; y++)
        for (uint32_t x = 0; x < img->width; x++) {
            unsigned sum[4] = {0, 0, 0, 0}, hits = 0;
            for (uint32_t j = 0; j < ss; j++)
                for (uint32_t i = 0; i < ss; i++) {
                    size_t k = (size_t)(y * ss + j) * t->w + (x * ss + i);
                    int drawn = t->near[k] > -INFINITY;
                    hits += (unsigned)drawn;
                    for (int c = 0; c < 3; c++)
                        sum[c] += t->rgb[3 * k + c];
                    sum[3] += drawn ? 255u : r->background[3];
                }
            uint8_t *p = img->rgba + 4 * ((size_t)y * img->width + x);
            unsigned n = ss * ss;
            for (int c = 0; c < 4; c++)
                p[c] = (uint8_t)((sum[c] + n / 2) / n);
            covered += hits > 0;
        }
    return covered;
}

fl_status fl_render_finish(fl_render *render, fl_image *image, fl_render_stats *stats,
                           fl_error *err)
{
    if (image) memset(image, 0, sizeof *image);
    if (!render || !image)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_render_finish: NULL argument");
    double bbox[6];
    render_target t;
    if (!scene_bbox(render, bbox))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "render: nothing to draw (no triangles, "
                       "balls or points)");
    fl_status st = target_init(&t, render, err);
    if (st == FL_OK && !fl_render_fit_camera(&render->opt, bbox, t.w, t.h, &t.cam))
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1, "render: the scene has no extent");
    image->rgba = st ? NULL : fl_alloc_array((size_t)render->opt.width * render->opt.height, 4);
    if (st == FL_OK && !image->rgba) st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    if (st == FL_OK) {
        for (int k = 0; k < 3; k++)
            t.eye[k] = t.cam.center[k] + t.cam.distance * t.cam.toward[k];
        /* A key light above and to the left of the viewer: shapes read best lit from there. */
        for (int k = 0; k < 3; k++)
            t.light[k] = -0.35 * t.cam.right[k] + 0.55 * t.cam.up[k] + 0.76 * t.cam.toward[k];
        double l =
            sqrt(t.light[0] * t.light[0] + t.light[1] * t.light[1] + t.light[2] * t.light[2]);
        for (int k = 0; k < 3; k++)
            t.light[k] /= l;
        const render_mesh *m = render->meshes.data;
        for (size_t i = 0; i < render->meshes.count; i++)
            fl_render_draw_mesh(&t, &m[i]);
        const render_sphere *s = render->spheres.data;
        for (size_t i = 0; i < render->spheres.count; i++)
            fl_render_draw_sphere(&t, &s[i]);
        image->width = render->opt.width;
        image->height = render->opt.height;
        size_t covered = resolve(&t, render, image);
        if (stats) {
            stats->width = image->width;
            stats->height = image->height;
            stats->pixels_covered = covered;
            stats->camera = t.cam;
            double ss = render->opt.supersample;
            stats->camera.scale /= ss;
            stats->camera.offset[0] /= ss;
            stats->camera.offset[1] /= ss;
        }
    } else {
        fl_image_free(image);
    }
    free(t.rgb);
    free(t.near);
    return st;
}

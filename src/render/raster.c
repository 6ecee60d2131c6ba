/* Triangles into the sample buffer: edge functions over the triangle's pixel box, a z-buffer on
 * the nearness value (linear in screen space in both projections: the camera-space depth for
 * orthographic, 1/w for perspective), perspective-correct interpolation of position, normal and
 * colour, and a wireframe drawn in the same pass from each sample's distance to the edges. */
#include <math.h>

#include "render/render_internal.h"

/* A triangle projected to sample pixels, with what its samples interpolate. */
typedef struct screen_tri {
    double x[3], y[3]; /* sample-pixel positions */
    double inv_w[3];   /* 1/w per vertex (1 for orthographic) */
    double nearness[3];
    double area;        /* twice the signed screen area */
    double edge_len[3]; /* length of the edge opposite each vertex, in samples */
} screen_tri;

static void project_tri(const render_target *t, const render_mesh *m, const uint32_t *v,
                        screen_tri *s)
{
    for (int i = 0; i < 3; i++) {
        double q[3];
        fl_render_project(&t->cam, m->xyz + 3 * (size_t)v[i], q);
        s->x[i] = q[0];
        s->y[i] = q[1];
        s->inv_w[i] = t->cam.orthographic ? 1 : 1 / q[2];
        /* Orthographic q[2] is -depth; negate so that larger is nearer in both cases. */
        s->nearness[i] = t->cam.orthographic ? -q[2] : 1 / q[2];
    }
    s->area = (s->x[1] - s->x[0]) * (s->y[2] - s->y[0]) - (s->x[2] - s->x[0]) * (s->y[1] - s->y[0]);
    for (int i = 0; i < 3; i++) {
        int a = (i + 1) % 3, b = (i + 2) % 3;
        s->edge_len[i] = hypot(s->x[b] - s->x[a], s->y[b] - s->y[a]);
    }
}

static double edge_fn(const screen_tri *s, int a, int b, double px, double py)
{
    return (s->x[b] - s->x[a]) * (py - s->y[a]) - (s->y[b] - s->y[a]) * (px - s->x[a]);
}

static void face_normal(const render_mesh *m, const uint32_t *v, double n[3])
{
    const double *a = m->xyz + 3 * (size_t)v[0], *b = m->xyz + 3 * (size_t)v[1],
                 *c = m->xyz + 3 * (size_t)v[2];
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
}

/* Shades the sample at barycentric b (screen space) and stores it. */
static void shade_sample(render_target *t, const render_mesh *m, const uint32_t *v,
                         const screen_tri *s, const double b[3], const double fn[3], size_t k)
{
    double pc[3], sum = 0;
    for (int i = 0; i < 3; i++)
        sum += pc[i] = b[i] * s->inv_w[i];
    double pos[3] = {0, 0, 0}, n[3] = {0, 0, 0}, col[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
        double f = pc[i] / sum;
        for (int c = 0; c < 3; c++) {
            pos[c] += f * m->xyz[3 * (size_t)v[i] + c];
            col[c] += f * m->rgb[3 * (size_t)v[i] + c];
            if (m->normals) n[c] += f * m->normals[3 * (size_t)v[i] + c];
        }
    }
    if (!m->normals)
        for (int c = 0; c < 3; c++)
            n[c] = fn[c];
    double view[3];
    if (t->cam.orthographic) {
        for (int c = 0; c < 3; c++)
            view[c] = t->cam.toward[c];
    } else {
        double len = 0;
        for (int c = 0; c < 3; c++) {
            view[c] = t->eye[c] - pos[c];
            len += view[c] * view[c];
        }
        len = sqrt(len);
        for (int c = 0; c < 3; c++)
            view[c] = len > 0 ? view[c] / len : t->cam.toward[c];
    }
    uint8_t base[3] = {(uint8_t)(col[0] + 0.5), (uint8_t)(col[1] + 0.5), (uint8_t)(col[2] + 0.5)};
    uint8_t *out = t->rgb + 3 * k;
    fl_render_shade(t, base, n, view, m->zebra ? m->zebra_stripes : 0, out);
    if (m->wireframe) {
        /* Distance to the edge opposite vertex i is b_i * |area| / |edge i| samples. Half a
         * pixel on each side of an edge makes a line about one pixel wide. */
        double half = 0.5 * t->ss;
        for (int i = 0; i < 3; i++)
            if (s->edge_len[i] > 0 && b[i] * fabs(s->area) / s->edge_len[i] < half) {
                for (int c = 0; c < 3; c++)
                    out[c] = (uint8_t)(out[c] / 5 + 20);
                break;
            }
    }
}

static void draw_triangle(render_target *t, const render_mesh *m, const uint32_t *v)
{
    screen_tri s;
    project_tri(t, m, v, &s);
    if (!(s.area != 0) || !isfinite(s.area)) return; /* seen edge-on: covers no sample */
    double x0 = fmin(s.x[0], fmin(s.x[1], s.x[2])), x1 = fmax(s.x[0], fmax(s.x[1], s.x[2]));
    double y0 = fmin(s.y[0], fmin(s.y[1], s.y[2])), y1 = fmax(s.y[0], fmax(s.y[1], s.y[2]));
    /* Samples sit at pixel centres (i + 0.5, j + 0.5). */
    long ia = (long)fmax(0, ceil(x0 - 0.5)), ib = (long)fmin(t->w - 1.0, floor(x1 - 0.5));
    long ja = (long)fmax(0, ceil(y0 - 0.5)), jb = (long)fmin(t->h - 1.0, floor(y1 - 0.5));
    double fn[3];
    face_normal(m, v, fn);
    for (long j = ja; j <= jb; j++)
        for (long i = ia; i <= ib; i++) {
            double px = i + 0.5, py = j + 0.5;
            double b[3] = {edge_fn(&s, 1, 2, px, py) / s.area, edge_fn(&s, 2, 0, px, py) / s.area,
                           edge_fn(&s, 0, 1, px, py) / s.area};
            /* Inclusive on the edges: a sample on an edge shared by two triangles is drawn by
             * both (the z-buffer keeps one), so no sample falls through a crack. */
            if (b[0] < 0 || b[1] < 0 || b[2] < 0) continue;
            double q = b[0] * s.nearness[0] + b[1] * s.nearness[1] + b[2] * s.nearness[2];
            size_t k = (size_t)j * t->w + (size_t)i;
            if (!(q > t->near[k])) continue;
            t->near[k] = q;
            shade_sample(t, m, v, &s, b, fn, k);
        }
}

void fl_render_draw_mesh(render_target *t, const render_mesh *m)
{
    for (size_t i = 0; i < m->triangle_count; i++)
        draw_triangle(t, m, m->tri + 3 * i);
}

fl_status fl_render_vertex_normals(const fl_mesh *mesh, double *normals, fl_error *err)
{
    if (!mesh || !normals || (mesh->vertex_count && !mesh->xyz) ||
        (mesh->triangle_count && !mesh->tri))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_render_vertex_normals: NULL argument");
    for (size_t i = 0; i < 3 * mesh->triangle_count; i++)
        if (mesh->tri[i] >= mesh->vertex_count)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "render: triangle %zu uses vertex %u of %zu", i / 3, mesh->tri[i],
                           mesh->vertex_count);
    for (size_t i = 0; i < 3 * mesh->vertex_count; i++)
        normals[i] = 0;
    render_mesh m = {.xyz = mesh->xyz};
    for (size_t t = 0; t < mesh->triangle_count; t++) {
        const uint32_t *v = mesh->tri + 3 * t;
        double n[3]; /* the cross product's length is twice the area: area weighting for free */
        face_normal(&m, v, n);
        for (int i = 0; i < 3; i++)
            for (int c = 0; c < 3; c++)
                normals[3 * (size_t)v[i] + c] += n[c];
    }
    for (size_t i = 0; i < mesh->vertex_count; i++) {
        double *n = normals + 3 * i, len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int c = 0; c < 3 && len > 0; c++)
            n[c] /= len;
    }
    return FL_OK;
}

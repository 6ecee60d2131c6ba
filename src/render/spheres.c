/* Spheres (balls and points) ray-cast per sample into the same z-buffer as the triangles: the
 * ray through a sample centre meets the sphere at the smaller root of a quadratic, which gives
 * the exact silhouette, depth and normal (no tessellation). */
#include <math.h>

#include "render/render_internal.h"

/* The sample rectangle that may see the sphere. Orthographic: centre +- r*scale. Perspective:
 * x/w over the box [x-r, x+r] x [w-r, w+r] is extreme at its corners, which bounds the
 * projection of the sphere (w - r > 0 because the eye is outside the scene's bounding sphere). */
static void sphere_box(const render_target *t, const double c[3], double r, double box[4])
{
    const fl_render_camera *cam = &t->cam;
    if (cam->orthographic) {
        box[0] = cam->offset[0] + cam->scale * (c[0] - r);
        box[1] = cam->offset[0] + cam->scale * (c[0] + r);
        box[2] = cam->offset[1] - cam->scale * (c[1] + r);
        box[3] = cam->offset[1] - cam->scale * (c[1] - r);
        return;
    }
    double w = cam->distance - c[2];
    box[0] = box[2] = INFINITY;
    box[1] = box[3] = -INFINITY;
    for (int i = 0; i < 4; i++) {
        double ww = w + ((i & 1) ? r : -r), d = (i & 2) ? r : -r;
        double x = cam->offset[0] + cam->scale * (c[0] + d) / ww;
        double y = cam->offset[1] - cam->scale * (c[1] + d) / ww;
        box[0] = fmin(box[0], x);
        box[1] = fmax(box[1], x);
        box[2] = fmin(box[2], y);
        box[3] = fmax(box[3], y);
    }
}

/* Hit of the ray through sample (px, py) with the sphere at camera-space centre c: returns 0 on
 * a miss, else the nearness and the camera-space unit normal. */
static int hit(const render_target *t, const double c[3], double r, double px, double py,
               double *nearness, double n[3])
{
    const fl_render_camera *cam = &t->cam;
    double u = (px - cam->offset[0]) / cam->scale, v = (cam->offset[1] - py) / cam->scale;
    if (cam->orthographic) {
        double dx = u - c[0], dy = v - c[1], rho2 = dx * dx + dy * dy;
        if (rho2 > r * r) return 0;
        double h = sqrt(r * r - rho2);
        *nearness = c[2] + h;
        n[0] = dx / r;
        n[1] = dy / r;
        n[2] = h / r;
        return 1;
    }
    /* Ray eye + s (u, v, -1) in camera space, eye = (0, 0, distance); s is the w of the hit. */
    double e[3] = {-c[0], -c[1], cam->distance - c[2]}, d[3] = {u, v, -1};
    double a = d[0] * d[0] + d[1] * d[1] + 1, b = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
    double cc = e[0] * e[0] + e[1] * e[1] + e[2] * e[2] - r * r;
    double disc = b * b - a * cc;
    if (disc < 0) return 0;
    double s = (-b - sqrt(disc)) / a;
    if (!(s > 0)) return 0;
    *nearness = 1 / s;
    for (int k = 0; k < 3; k++)
        n[k] = (e[k] + s * d[k]) / r;
    return 1;
}

void fl_render_draw_sphere(render_target *t, const render_sphere *sp)
{
    if (!(sp->r > 0)) return;
    const fl_render_camera *cam = &t->cam;
    double c[3], box[4];
    fl_render_camera_space(cam, sp->c, c);
    sphere_box(t, c, sp->r, box);
    long ia = (long)fmax(0, ceil(box[0] - 0.5)), ib = (long)fmin(t->w - 1.0, floor(box[1] - 0.5));
    long ja = (long)fmax(0, ceil(box[2] - 0.5)), jb = (long)fmin(t->h - 1.0, floor(box[3] - 0.5));
    for (long j = ja; j <= jb; j++)
        for (long i = ia; i <= ib; i++) {
            double q, n[3];
            if (!hit(t, c, sp->r, i + 0.5, j + 0.5, &q, n)) continue;
            size_t k = (size_t)j * t->w + (size_t)i;
            if (!(q > t->near[k])) continue;
            t->near[k] = q;
            double nw[3], view[3], len = 0;
            for (int a = 0; a < 3; a++) {
                nw[a] = n[0] * cam->right[a] + n[1] * cam->up[a] + n[2] * cam->toward[a];
                view[a] = cam->toward[a];
            }
            if (!cam->orthographic) {
                double pos[3];
                for (int a = 0; a < 3; a++) {
                    pos[a] = sp->c[a] + sp->r * nw[a];
                    view[a] = t->eye[a] - pos[a];
                    len += view[a] * view[a];
                }
                len = sqrt(len);
                for (int a = 0; a < 3; a++)
                    view[a] /= len;
            }
            fl_render_shade(t, sp->rgb, nw, view, 0, t->rgb + 3 * k);
        }
}

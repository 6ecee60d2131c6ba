/* The camera: a view direction from (azimuth, elevation) and a projection fitted so that the
 * projected bounding box of the scene fills the image up to the margin. */
#include <math.h>

#include "render/render_internal.h"

#define PI 3.14159265358979323846

void fl_render_camera_space(const fl_render_camera *cam, const double p[3], double out[3])
{
    double d[3] = {p[0] - cam->center[0], p[1] - cam->center[1], p[2] - cam->center[2]};
    out[0] = d[0] * cam->right[0] + d[1] * cam->right[1] + d[2] * cam->right[2];
    out[1] = d[0] * cam->up[0] + d[1] * cam->up[1] + d[2] * cam->up[2];
    out[2] = d[0] * cam->toward[0] + d[1] * cam->toward[1] + d[2] * cam->toward[2];
}

void fl_render_project(const fl_render_camera *cam, const double p[3], double out[3])
{
    double c[3];
    fl_render_camera_space(cam, p, c);
    double w = 1;
    if (cam->orthographic) {
        out[2] = -c[2];
    } else {
        w = cam->distance - c[2];
        out[2] = w;
    }
    out[0] = cam->offset[0] + cam->scale * c[0] / w;
    out[1] = cam->offset[1] - cam->scale * c[1] / w;
}

/* toward = (cos e cos a, cos e sin a, sin e); right is horizontal, (-sin a, cos a, 0), and
 * up = toward x right, so (right, up, toward) is right-handed: a triangle counter-clockwise
 * seen from the eye is counter-clockwise on screen with y up. right is well defined even at
 * the poles (e = +-90), where up then turns with the azimuth as a turntable would. */
static void view_basis(fl_render_camera *cam, double azimuth, double elevation)
{
    double a = azimuth * PI / 180, e = elevation * PI / 180;
    double t[3] = {cos(e) * cos(a), cos(e) * sin(a), sin(e)};
    double r[3] = {-sin(a), cos(a), 0};
    double u[3] = {t[1] * r[2] - t[2] * r[1], t[2] * r[0] - t[0] * r[2], t[0] * r[1] - t[1] * r[0]};
    for (int k = 0; k < 3; k++) {
        cam->toward[k] = t[k];
        cam->right[k] = r[k];
        cam->up[k] = u[k];
    }
}

int fl_render_fit_camera(const fl_render_options *opt, const double bbox[6], uint32_t w, uint32_t h,
                         fl_render_camera *cam)
{
    view_basis(cam, opt->azimuth, opt->elevation);
    double radius2 = 0;
    for (int k = 0; k < 3; k++) {
        cam->center[k] = bbox[k] / 2 + bbox[3 + k] / 2;
        double half = bbox[3 + k] / 2 - bbox[k] / 2;
        radius2 += half * half;
    }
    double radius = sqrt(radius2);
    if (!(radius > 0) || !isfinite(radius)) return 0;
    cam->orthographic = opt->orthographic != 0;
    /* The eye sits where the bounding sphere just fills the field of view, so it is outside
     * the sphere and every drawn point is strictly in front of it (w > 0, no clipping). */
    cam->distance = cam->orthographic ? 0 : radius / sin(opt->fov * PI / 360);
    cam->scale = 1;
    cam->offset[0] = cam->offset[1] = 0;
    /* Projected extent of the 8 corners with unit scale: the projection of the box (convex)
     * is the hull of the projected corners, and the scene lies inside the box. */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < 8; i++) {
        double p[3] = {bbox[(i & 1) ? 3 : 0], bbox[(i & 2) ? 4 : 1], bbox[(i & 4) ? 5 : 2]}, q[3];
        fl_render_project(cam, p, q);
        q[1] = -q[1];
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], q[k]);
            hi[k] = fmax(hi[k], q[k]);
        }
    }
    double avail_w = w * (1 - 2 * opt->margin), avail_h = h * (1 - 2 * opt->margin);
    double ex = hi[0] - lo[0], ey = hi[1] - lo[1];
    double s = INFINITY;
    if (ex > 0) s = fmin(s, avail_w / ex);
    if (ey > 0) s = fmin(s, avail_h / ey);
    if (!isfinite(s)) /* a segment seen end-on */
        s = fmin(avail_w, avail_h) / (2 * (cam->orthographic ? radius : radius / cam->distance));
    cam->scale = s;
    cam->offset[0] = w / 2.0 - s * (lo[0] + hi[0]) / 2;
    cam->offset[1] = h / 2.0 + s * (lo[1] + hi[1]) / 2;
    return 1;
}

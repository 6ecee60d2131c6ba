/* Shading: Lambert diffuse + Blinn-Phong specular from one key light, reflection lines (zebra)
 * and the colormaps for per-vertex scalars. */
#include <math.h>
#include <string.h>

#include "render/render_internal.h"

#define PI 3.14159265358979323846

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static uint8_t to_byte(double v)
{
    return (uint8_t)(v <= 0 ? 0 : v >= 255 ? 255 : v + 0.5);
}

/* Reflection lines: the environment is a family of parallel light tubes at infinity along the
 * camera's right axis, so the stripe a surface point shows depends only on the angle of the
 * reflected view ray around that axis. Stripes bend wherever the normal field does: a kink
 * (G0 only) breaks them, a curvature jump (G1 only) kinks them, and they flow smoothly across
 * G2 surfaces (the usual car-body check). */
static int zebra_stripe(const render_target *t, const double n[3], const double v[3],
                        double stripes)
{
    double nv = dot3(n, v), r[3];
    for (int k = 0; k < 3; k++)
        r[k] = 2 * nv * n[k] - v[k];
    double angle = atan2(dot3(r, t->cam.up), dot3(r, t->cam.toward));
    return (int)floor(angle / PI * stripes) & 1;
}

void fl_render_shade(const render_target *t, const uint8_t base[3], const double n_in[3],
                     const double v[3], double zebra, uint8_t out[3])
{
    double n[3] = {n_in[0], n_in[1], n_in[2]};
    double len = sqrt(dot3(n, n));
    if (!(len > 0)) {
        for (int k = 0; k < 3; k++)
            n[k] = v[k];
        len = 1;
    }
    /* Both sides of a surface are lit alike: open or misoriented meshes still read. */
    double sign = dot3(n, v) < 0 ? -1 : 1;
    for (int k = 0; k < 3; k++)
        n[k] *= sign / len;
    double diffuse = fmax(0, dot3(n, t->light));
    if (zebra > 0) {
        double c = zebra_stripe(t, n, v, zebra) ? 235 : 25;
        for (int k = 0; k < 3; k++)
            out[k] = to_byte(c * (0.55 + 0.45 * diffuse));
        return;
    }
    double h[3] = {t->light[0] + v[0], t->light[1] + v[1], t->light[2] + v[2]};
    double hl = sqrt(dot3(h, h));
    double spec = hl > 0 ? pow(fmax(0, dot3(n, h) / hl), 48) : 0;
    for (int k = 0; k < 3; k++)
        out[k] = to_byte(base[k] * (0.22 + 0.78 * diffuse) + 90 * spec);
}

/* Colormap control points, evenly spaced in t, linearly interpolated. Cool-warm after
 * Moreland, "Diverging Color Maps for Scientific Visualization" (2009); viridis sampled from
 * matplotlib's table at t = 0, 0.25, 0.5, 0.75, 1. */
static const uint8_t coolwarm[5][3] = {
    {59, 76, 192}, {141, 176, 254}, {221, 221, 221}, {244, 154, 123}, {180, 4, 38}};
static const uint8_t viridis[5][3] = {
    {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
static const uint8_t gray[2][3] = {{0, 0, 0}, {255, 255, 255}};

void fl_render_colormap_rgba(fl_render_colormap map, double t, uint8_t rgba[4])
{
    const uint8_t(*table)[3] = map == FL_RENDER_VIRIDIS ? viridis
                               : map == FL_RENDER_GRAY  ? gray
                                                        : coolwarm;
    int n = map == FL_RENDER_GRAY ? 2 : 5;
    rgba[3] = 255;
    if (isnan(t)) {
        memset(rgba, 128, 3);
        return;
    }
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double x = t * (n - 1);
    int i = (int)x;
    if (i >= n - 1) i = n - 2;
    double f = x - i;
    for (int k = 0; k < 3; k++)
        rgba[k] = to_byte(table[i][k] + f * (table[i + 1][k] - table[i][k]));
}

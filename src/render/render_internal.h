/* Internal interface of src/render: the scene a fl_render collects and the pieces that turn it
 * into pixels (camera fitting, triangle and sphere rasterization, shading). */
#ifndef FL_RENDER_INTERNAL_H
#define FL_RENDER_INTERNAL_H

#include "core/core.h"

/* One mesh as added: its own copy of positions, per-vertex colours and (optional) normals. */
typedef struct render_mesh {
    size_t vertex_count, triangle_count;
    double *xyz;
    uint32_t *tri;
    double *normals; /* NULL: face normals */
    uint8_t *rgb;    /* 3 per vertex */
    int wireframe, zebra;
    double zebra_stripes;
} render_mesh;

/* A sphere: centre, radius, colour. Balls and points both become spheres. */
typedef struct render_sphere {
    double c[3], r;
    uint8_t rgb[3];
} render_sphere;

struct fl_render {
    fl_render_options opt; /* defaults filled in */
    uint8_t background[4];
    fl_vec meshes;  /* render_mesh */
    fl_vec spheres; /* render_sphere */
};

/* The sample buffer: ss*width x ss*height samples, each a colour and a nearness (larger is
 * nearer; -inf where nothing was drawn). */
typedef struct render_target {
    uint32_t w, h; /* in samples */
    int ss;        /* samples per pixel side */
    uint8_t *rgb;  /* 3 per sample */
    double *near;
    fl_render_camera cam; /* in sample pixels */
    double eye[3];        /* perspective eye position */
    double light[3];      /* unit direction towards the light (world) */
} render_target;

/* Fits cam to the bbox (min xyz, max xyz) for an image of w x h pixels (camera.c). Returns 0
 * when the bbox has no extent. */
int fl_render_fit_camera(const fl_render_options *opt, const double bbox[6], uint32_t w, uint32_t h,
                         fl_render_camera *cam);
/* Camera-space coordinates of p: along right, up, toward, relative to the centre. */
void fl_render_camera_space(const fl_render_camera *cam, const double p[3], double out[3]);

/* Rasterizes into t (raster.c, spheres.c). */
void fl_render_draw_mesh(render_target *t, const render_mesh *m);
void fl_render_draw_sphere(render_target *t, const render_sphere *s);

/* Lit colour of a surface point with unit normal n seen along unit v (towards the eye) (shade.c).
 * zebra > 0: reflection-line stripes with that many stripe pairs a half turn. */
void fl_render_shade(const render_target *t, const uint8_t base[3], const double n[3],
                     const double v[3], double zebra, uint8_t out[3]);

#endif /* FL_RENDER_INTERNAL_H */

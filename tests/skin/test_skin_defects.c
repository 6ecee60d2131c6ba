/* The locator of a skin mesh's false handles and bubbles (src/skin/skin_defects.c), on meshes
 * built here whose topology is known by construction:
 *  - a coarse torus (genus 1) beside a fine sphere far away: with no balls behind it the
 *    torus's handle is boxed, and every box holds the torus and none meets the sphere;
 *  - the same torus with a ring of balls along its core circle (the union has the tunnel, so
 *    the handle is the skin's own): nothing is boxed;
 *  - a large and a small sphere with one component too many: the small one is boxed;
 *  - the component count of skin_mesh_components on these meshes, and FL_ERR_INPUT for an open
 *    mesh. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "fl_test.h"
#include "skin/skin_internal.h"

#define PI 3.14159265358979323846

typedef struct builder {
    double *xyz;
    uint32_t *tri;
    size_t nv, nt, cv, ct;
} builder;

static uint32_t vertex(builder *b, double x, double y, double z)
{
    if (b->nv == b->cv) {
        b->cv = b->cv ? 2 * b->cv : 64;
        b->xyz = realloc(b->xyz, b->cv * 3 * sizeof(double));
    }
    b->xyz[3 * b->nv] = x;
    b->xyz[3 * b->nv + 1] = y;
    b->xyz[3 * b->nv + 2] = z;
    return (uint32_t)b->nv++;
}

static void triangle(builder *b, uint32_t p, uint32_t q, uint32_t r)
{
    if (b->nt == b->ct) {
        b->ct = b->ct ? 2 * b->ct : 64;
        b->tri = realloc(b->tri, b->ct * 3 * sizeof(uint32_t));
    }
    b->tri[3 * b->nt] = p;
    b->tri[3 * b->nt + 1] = q;
    b->tri[3 * b->nt + 2] = r;
    b->nt++;
}

/* Torus about the z axis through c: core radius R, tube radius r, nu x nv quads. */
static void add_torus(builder *b, const double c[3], double R, double r, int nu, int nv)
{
    uint32_t first = (uint32_t)b->nv;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double u = 2 * PI * i / nu, v = 2 * PI * j / nv;
            vertex(b, c[0] + (R + r * cos(v)) * cos(u), c[1] + (R + r * cos(v)) * sin(u),
                   c[2] + r * sin(v));
        }
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            uint32_t a = first + (uint32_t)(i * nv + j),
                     p = first + (uint32_t)(((i + 1) % nu) * nv + j),
                     q = first + (uint32_t)(((i + 1) % nu) * nv + (j + 1) % nv),
                     s = first + (uint32_t)(i * nv + (j + 1) % nv);
            triangle(b, a, p, q);
            triangle(b, a, q, s);
        }
}

/* Sphere of radius r about c: nu longitudes, nv latitude bands, two pole vertices. */
static void add_sphere(builder *b, const double c[3], double r, int nu, int nv)
{
    uint32_t south = vertex(b, c[0], c[1], c[2] - r);
    uint32_t first = (uint32_t)b->nv;
    for (int j = 1; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            double u = 2 * PI * i / nu, v = -PI / 2 + PI * j / nv;
            vertex(b, c[0] + r * cos(v) * cos(u), c[1] + r * cos(v) * sin(u), c[2] + r * sin(v));
        }
    uint32_t north = vertex(b, c[0], c[1], c[2] + r);
    for (int i = 0; i < nu; i++) {
        uint32_t i1 = (uint32_t)((i + 1) % nu);
        triangle(b, south, first + i1, first + (uint32_t)i);
        for (int j = 0; j + 2 < nv; j++) {
            uint32_t a = first + (uint32_t)(j * nu + i), p = first + (uint32_t)(j * nu) + i1,
                     q = first + (uint32_t)((j + 1) * nu) + i1,
                     s = first + (uint32_t)((j + 1) * nu + i);
            triangle(b, a, p, q);
            triangle(b, a, q, s);
        }
        uint32_t top = first + (uint32_t)((nv - 2) * nu);
        triangle(b, north, top + (uint32_t)i, top + i1);
    }
}

static fl_mesh as_mesh(builder *b)
{
    fl_mesh m = {0};
    m.xyz = b->xyz;
    m.tri = b->tri;
    m.vertex_count = b->nv;
    m.triangle_count = b->nt;
    return m;
}

static int box_holds(const skin_box *x, const double p[3])
{
    for (int c = 0; c < 3; c++)
        if (!(p[c] >= x->lo[c] && p[c] <= x->hi[c])) return 0;
    return 1;
}

static int box_meets_ball(const skin_box *x, const double c[3], double r)
{
    double d2 = 0;
    for (int k = 0; k < 3; k++) {
        double e = fmax(fmax(x->lo[k] - c[k], c[k] - x->hi[k]), 0);
        d2 += e * e;
    }
    return d2 < r * r;
}

static const double torus_c[3] = {0.05, -0.03, 0.02}, sphere_c[3] = {40, 1, -2};

static void test_false_handle_is_boxed_and_nothing_else(void)
{
    builder b = {0};
    add_torus(&b, torus_c, 1, 0.4, 12, 6);
    add_sphere(&b, sphere_c, 6, 120, 60);
    fl_mesh m = as_mesh(&b);
    CHECK_EQ_INT(skin_mesh_components(&m), 2);
    CHECK_EQ_INT((long long)m.vertex_count - (long long)m.triangle_count / 2, 2); /* 0 + 2 */
    fl_vec boxes;
    fl_vec_init(&boxes, sizeof(skin_box));
    fl_error err;
    CHECK_STATUS(skin_mesh_defects(&m, NULL, 0, 1, 0, &boxes, &err), FL_OK, &err);
    CHECK_MSG(boxes.count > 0, "no box round the torus");
    for (size_t i = 0; i < boxes.count; i++) {
        const skin_box *x = (const skin_box *)boxes.data + i;
        CHECK_MSG(box_holds(x, torus_c) && !box_meets_ball(x, sphere_c, 6.01),
                  "box %zu: (%g %g %g) - (%g %g %g)", i, x->lo[0], x->lo[1], x->lo[2], x->hi[0],
                  x->hi[1], x->hi[2]);
        CHECK(x->h > 0 && x->h < 1);
    }
    /* handles not asked for: nothing */
    boxes.count = 0;
    CHECK_STATUS(skin_mesh_defects(&m, NULL, 0, 0, 0, &boxes, &err), FL_OK, &err);
    CHECK_EQ_INT(boxes.count, 0);
    fl_vec_free(&boxes);
    free(b.xyz);
    free(b.tri);
}

static void test_handle_of_the_balls_is_not_boxed(void)
{
    builder b = {0};
    add_torus(&b, torus_c, 1, 0.4, 12, 6);
    add_sphere(&b, sphere_c, 6, 120, 60);
    fl_mesh m = as_mesh(&b);
    /* 16 balls of radius 0.45 on the core circle: neighbours 0.39 apart overlap, a ring */
    double balls[16 * 4];
    for (int i = 0; i < 16; i++) {
        double u = 2 * PI * i / 16;
        balls[4 * i] = torus_c[0] + cos(u);
        balls[4 * i + 1] = torus_c[1] + sin(u);
        balls[4 * i + 2] = torus_c[2];
        balls[4 * i + 3] = 0.45 * 0.45;
    }
    long long betti[3];
    fl_error err;
    CHECK_STATUS(fl_balls_union_betti(balls, 16, betti, &err), FL_OK, &err);
    CHECK(betti[0] == 1 && betti[1] == 1 && betti[2] == 0);
    fl_vec boxes;
    fl_vec_init(&boxes, sizeof(skin_box));
    CHECK_STATUS(skin_mesh_defects(&m, balls, 16, 1, 0, &boxes, &err), FL_OK, &err);
    CHECK_MSG(boxes.count == 0, "%zu boxes round a handle the balls have", boxes.count);
    /* half of the ring: no tunnel, the handle is false again */
    boxes.count = 0;
    CHECK_STATUS(skin_mesh_defects(&m, balls, 8, 1, 0, &boxes, &err), FL_OK, &err);
    CHECK(boxes.count > 0);
    fl_vec_free(&boxes);
    free(b.xyz);
    free(b.tri);
}

static void test_small_component_is_boxed(void)
{
    builder b = {0};
    const double big_c[3] = {0, 0, 0}, small_c[3] = {9, 0.5, 0};
    add_sphere(&b, big_c, 5, 60, 30);
    add_sphere(&b, small_c, 0.1, 8, 4);
    fl_mesh m = as_mesh(&b);
    CHECK_EQ_INT(skin_mesh_components(&m), 2);
    fl_vec boxes;
    fl_vec_init(&boxes, sizeof(skin_box));
    fl_error err;
    CHECK_STATUS(skin_mesh_defects(&m, NULL, 0, 0, 1, &boxes, &err), FL_OK, &err);
    CHECK_EQ_INT(boxes.count, 1);
    if (boxes.count == 1) {
        const skin_box *x = boxes.data;
        CHECK(box_holds(x, small_c) && !box_meets_ball(x, big_c, 5.01));
        CHECK(x->h > 0 && x->h <= 0.1);
    }
    fl_vec_free(&boxes);
    free(b.xyz);
    free(b.tri);
}

static void test_open_mesh_is_refused(void)
{
    builder b = {0};
    add_sphere(&b, sphere_c, 1, 8, 4);
    b.nt--; /* a hole */
    fl_mesh m = as_mesh(&b);
    fl_vec boxes;
    fl_vec_init(&boxes, sizeof(skin_box));
    fl_error err;
    CHECK_EQ_INT(skin_mesh_defects(&m, NULL, 0, 1, 0, &boxes, &err), FL_ERR_INPUT);
    CHECK_EQ_INT(boxes.count, 0);
    fl_vec_free(&boxes);
    free(b.xyz);
    free(b.tri);
}

FL_TEST_MAIN(FL_TEST_CASE(test_false_handle_is_boxed_and_nothing_else),
             FL_TEST_CASE(test_handle_of_the_balls_is_not_boxed),
             FL_TEST_CASE(test_small_component_is_boxed), FL_TEST_CASE(test_open_mesh_is_refused))

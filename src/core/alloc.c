/* Checked allocation and growable arrays. Sizes come from untrusted files (a PLY header can
 * claim 2^60 vertices), so every multiplication is checked before it reaches malloc. */
#include <stdlib.h>
#include <string.h>

#include "core/core.h"

void *fl_alloc_array(size_t n, size_t size)
{
    if (size && n > SIZE_MAX / size) return NULL;
    return malloc(n * size != 0 ? n * size : 1);
}

void *fl_calloc_array(size_t n, size_t size)
{
    if (size && n > SIZE_MAX / size) return NULL;
    return calloc(n ? n : 1, size ? size : 1);
}

void *fl_realloc_array(void *p, size_t n, size_t size)
{
    if (size && n > SIZE_MAX / size) return NULL;
    return realloc(p, n * size != 0 ? n * size : 1);
}

void fl_vec_init(fl_vec *v, size_t elem)
{
    v->data = NULL;
    v->count = 0;
    v->capacity = 0;
    v->elem = elem;
}

int fl_vec_reserve(fl_vec *v, size_t count)
{
    if (count <= v->capacity) return 0;
    size_t cap = v->capacity ? v->capacity : 16;
    while (cap < count) {
        if (cap > SIZE_MAX / 2) return -1;
        cap *= 2;
    }
    void *p = fl_realloc_array(v->data, cap, v->elem);
    if (!p) return -1;
    v->data = p;
    v->capacity = cap;
    return 0;
}

int fl_vec_push(fl_vec *v, const void *src, size_t n)
{
    if (n == 0) return 0; /* memcpy from a NULL src of length 0 is still undefined */
    if (n > SIZE_MAX - v->count) return -1;
    if (fl_vec_reserve(v, v->count + n)) return -1;
    char *dst = (char *)v->data + v->count * v->elem;
    if (src)
        memcpy(dst, src, n * v->elem);
    else
        memset(dst, 0, n * v->elem);
    v->count += n;
    return 0;
}

void fl_vec_free(fl_vec *v)
{
    free(v->data);
    v->data = NULL;
    v->count = v->capacity = 0;
}

void *fl_vec_release(fl_vec *v)
{
    void *p = v->data;
    if (p && v->count && v->count < v->capacity) {
        void *q = realloc(p, v->count * v->elem);
        if (q) p = q;
    }
    v->data = NULL;
    v->count = v->capacity = 0;
    return p;
}

void fl_points_free(fl_points *points)
{
    if (!points) return;
    free(points->coords);
    memset(points, 0, sizeof *points);
}

void fl_mesh_free(fl_mesh *mesh)
{
    if (!mesh) return;
    free(mesh->xyz);
    free(mesh->tri);
    memset(mesh, 0, sizeof *mesh);
}

void fl_polygon_free(fl_polygon *polygon)
{
    if (!polygon) return;
    free(polygon->xy);
    free(polygon->ring_start);
    free(polygon->polygon_start);
    memset(polygon, 0, sizeof *polygon);
}

void fl_balls_free(fl_balls *balls)
{
    if (!balls) return;
    free(balls->xyzw);
    memset(balls, 0, sizeof *balls);
}

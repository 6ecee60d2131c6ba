/* Dynamic queries on the edge-collapse hierarchy (Guéziec §5.1, §5.2) against brute force over
 * every triangle: one cursor follows random walks (small steps: the refined mesh and queue are
 * kept, intervals widened by δ), walks broken by jumps (the reset to the base mesh), and rigid
 * motions of the mesh (the query carried into the mesh's frame); on a closed noisy torus, an
 * open grid, a mesh with degenerate / non-manifold / repeated triangles and a soup. Every
 * answer: the same triangle or an equidistant one, distance to 1e-12 relative. */
#include "sweep/collapse_internal.h"
#include "test_collapse_meshes.h"

static fl_sweep_collapse *build(const fl_mesh *m)
{
    fl_sweep_collapse *h = NULL;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_build(m, NULL, &h, &err), FL_OK, &err);
    return h;
}

/* Step i of a walk around the mesh: a smoothed random direction of length `step` * scale,
 * pulled back towards the mesh's middle so the walk stays near the surface; every `jump_every`
 * steps (0: never) the point jumps to a random vertex's neighbourhood or far away. */
typedef struct walker {
    double p[3], dir[3], step, scale;
    int jump_every;
} walker;

static void walker_step(walker *w, const fl_mesh *m, int i)
{
    if (w->jump_every && i % w->jump_every == w->jump_every - 1) {
        size_t v = (size_t)(fl_test_rand01(&cm_rng) * (double)m->vertex_count);
        double far = i % (2 * w->jump_every) == w->jump_every - 1 ? 50 : 0.05;
        for (int c = 0; c < 3; c++)
            w->p[c] = m->xyz[3 * v + c] + cm_rand(-far, far) * w->scale;
        return;
    }
    for (int c = 0; c < 3; c++) {
        w->dir[c] = 0.8 * w->dir[c] + cm_rand(-1, 1) - 0.02 * w->p[c] / w->scale;
    }
    double n = sqrt(w->dir[0] * w->dir[0] + w->dir[1] * w->dir[1] + w->dir[2] * w->dir[2]);
    for (int c = 0; c < 3 && n > 0; c++)
        w->p[c] += w->dir[c] / n * w->step * w->scale;
}

/* A walk of `steps` queries through one cursor, each checked against brute force; returns the
 * distances the cursor computed and *fresh those of the same queries each from the base mesh. */
static size_t check_walk(const fl_mesh *m, const fl_sweep_collapse *h, double step, int jump_every,
                         int steps, size_t *fresh)
{
    fl_sweep_collapse_cursor *c = NULL;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &c, &err), FL_OK, &err);
    if (!c) return 0;
    walker w = {{0, 0, 0}, {0, 0, 0}, step, mesh_scale(m), jump_every};
    memcpy(w.p, m->xyz, sizeof w.p); /* start at a vertex */
    size_t cost = 0;
    *fresh = 0;
    for (int i = 0; i < steps; i++) {
        walker_step(&w, m, i);
        fl_closest r, f;
        CHECK_STATUS(fl_sweep_collapse_cursor_closest(c, w.p, 0.0, &r, &err), FL_OK, &err);
        check_exact(m, w.p, &r);
        cost += r.visited;
        CHECK_STATUS(fl_sweep_collapse_closest(h, w.p, 1, 0.0, &f, &err), FL_OK, &err);
        *fresh += f.visited;
    }
    fl_sweep_collapse_cursor_free(c);
    return cost;
}

/* Walks with steps of 0.1 % and 2 % of the mesh's size, and a walk broken by jumps, on one
 * mesh; slow walks must cost less than answering each query from the base mesh (§5.1). */
static void check_mesh_walks(fl_mesh m, const char *name, int coherent_cheaper)
{
    fl_sweep_collapse *h = build(&m);
    if (h) {
        size_t fresh, slow = check_walk(&m, h, 0.001, 0, 300, &fresh);
        printf("  %s: slow walk %zu distances through the cursor, %zu from the base mesh\n", name,
               slow, fresh);
        if (coherent_cheaper) CHECK(2 * slow < fresh);
        size_t fast = check_walk(&m, h, 0.02, 0, 200, &fresh);
        printf("  %s: fast walk %zu / %zu\n", name, fast, fresh);
        size_t jumpy = check_walk(&m, h, 0.003, 7, 210, &fresh);
        printf("  %s: walk with jumps %zu / %zu\n", name, jumpy, fresh);
    }
    fl_sweep_collapse_free(h);
    cm_free(&m);
}

static void test_walks_closed(void)
{
    check_mesh_walks(cm_noisy_torus(40, 16, 0.05), "torus", 1);
}

static void test_walks_open(void)
{
    check_mesh_walks(cm_open_grid(20, 0.02), "open grid", 1);
}

static void test_walks_degenerate(void)
{
    check_mesh_walks(cm_messy(14), "messy", 0);
}

static void test_walks_soup(void)
{
    check_mesh_walks(cm_soup(150, 0.08), "soup", 0);
}

/* A rotation by `angle` about the unit axis (x, y, z) (Rodrigues), with translation t. */
static fl_sweep_pose axis_pose(double x, double y, double z, double angle, const double *t)
{
    double c = cos(angle), s = sin(angle), k = 1 - c;
    fl_sweep_pose p = {{c + x * x * k, x * y * k - z * s, x * z * k + y * s,
                        y * x * k + z * s, c + y * y * k, y * z * k - x * s,
                        z * x * k - y * s, z * y * k + x * s, c + z * z * k},
                       {t[0], t[1], t[2]}};
    return p;
}

/* The mesh `rest` moved by pose into `moved` (same triangles). */
static void move_mesh(const fl_sweep_pose *p, const fl_mesh *rest, fl_mesh *moved)
{
    for (size_t v = 0; v < rest->vertex_count; v++) {
        const double *a = rest->xyz + 3 * v;
        for (int i = 0; i < 3; i++)
            moved->xyz[3 * v + i] =
                p->t[i] + p->r[3 * i] * a[0] + p->r[3 * i + 1] * a[1] + p->r[3 * i + 2] * a[2];
    }
}

/* §5.2: the mesh tumbles and drifts a little each frame (sometimes a large turn) while the
 * query walks; every answer is exact for the moved mesh, `point` in the world frame. */
static void check_rigid(fl_mesh m, const char *name, int coherent_cheaper)
{
    fl_sweep_collapse *h = build(&m);
    fl_mesh moved = cm_alloc(m.vertex_count, m.triangle_count);
    memcpy(moved.tri, m.tri, 3 * m.triangle_count * sizeof(uint32_t));
    fl_sweep_collapse_cursor *c = NULL;
    fl_error err = {0};
    if (h) CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &c, &err), FL_OK, &err);
    double s = mesh_scale(&m), ax[3] = {0.3, -0.5, 0.8}, n = sqrt(0.09 + 0.25 + 0.64);
    double q[3] = {0.4 * s, 0.1 * s, 0.2 * s}, t[3] = {0, 0, 0};
    size_t cost = 0, fresh = 0;
    for (int f = 0; c && f < 240; f++) {
        double angle = 0.004 * f + (f >= 160 ? 2.0 : 0); /* a large turn at frame 160 */
        for (int i = 0; i < 3; i++) {
            t[i] += 0.001 * s * (i + 1);
            q[i] += cm_rand(-0.002, 0.002) * s;
        }
        fl_sweep_pose pose = axis_pose(ax[0] / n, ax[1] / n, ax[2] / n, angle, t);
        move_mesh(&pose, &m, &moved);
        fl_closest r, one;
        CHECK_STATUS(fl_sweep_collapse_cursor_closest_posed(c, &pose, q, 0.0, &r, &err), FL_OK,
                     &err);
        check_exact(&moved, q, &r);
        cost += r.visited;
        /* the same query from the base mesh, through a fresh cursor */
        fl_sweep_collapse_cursor *c1 = NULL;
        CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &c1, &err), FL_OK, &err);
        CHECK_STATUS(fl_sweep_collapse_cursor_closest_posed(c1, &pose, q, 0.0, &one, &err), FL_OK,
                     &err);
        fl_sweep_collapse_cursor_free(c1);
        CHECK_NEAR(one.distance, r.distance, 1e-12 * (s + fabs(q[0]) + fabs(q[1]) + fabs(q[2])));
        fresh += one.visited;
    }
    printf("  %s, rigid motion: %zu distances through the cursor, %zu from the base mesh\n", name,
           cost, fresh);
    if (coherent_cheaper) CHECK(2 * cost < fresh);
    fl_sweep_collapse_cursor_free(c);
    fl_sweep_collapse_free(h);
    cm_free(&moved);
    cm_free(&m);
}

static void test_rigid_closed(void)
{
    check_rigid(cm_noisy_torus(36, 14, 0.05), "torus", 1);
}

static void test_rigid_open_degenerate(void)
{
    check_rigid(cm_messy(12), "messy", 0);
}

/* fl_sweep_collapse_cursor_reset: after a walk has refined the mesh, a reset query does exactly
 * the work of a fresh cursor (same triangles computed) and answers exactly. */
static void test_reset_matches_fresh(void)
{
    fl_mesh m = cm_noisy_torus(30, 12, 0.05);
    fl_sweep_collapse *h = build(&m);
    fl_sweep_collapse_cursor *c = NULL;
    fl_error err = {0};
    if (h) CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &c, &err), FL_OK, &err);
    double p[3] = {1.3, 0.0, 0.1};
    for (int i = 0; c && i < 60; i++) {
        fl_closest r, f;
        p[0] += cm_rand(-0.01, 0.01), p[1] += cm_rand(-0.01, 0.01);
        CHECK_STATUS(fl_sweep_collapse_cursor_closest(c, p, 0.0, &r, &err), FL_OK, &err);
        if (i % 10 != 9) continue;
        fl_sweep_collapse_cursor_reset(c);
        CHECK_STATUS(fl_sweep_collapse_cursor_closest(c, p, 0.0, &r, &err), FL_OK, &err);
        CHECK_STATUS(fl_sweep_collapse_closest(h, p, 1, 0.0, &f, &err), FL_OK, &err);
        check_exact(&m, p, &r);
        CHECK(!r.reused && r.visited == f.visited && r.element == f.element);
    }
    fl_sweep_collapse_cursor_reset(NULL);
    fl_sweep_collapse_cursor_free(c);
    fl_sweep_collapse_free(h);
    cm_free(&m);
}

/* Bad poses and arguments are rejected with the documented codes, and the cursor still answers
 * exactly afterwards. */
static void test_posed_bad_input(void)
{
    fl_mesh m = cm_noisy_torus(12, 8, 0.02);
    fl_sweep_collapse *h = build(&m);
    fl_sweep_collapse_cursor *c = NULL;
    fl_error err = {0};
    if (h) CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &c, &err), FL_OK, &err);
    double q[3] = {0.5, 0.5, 0.5}, t0[3] = {0, 0, 0};
    fl_sweep_pose id = axis_pose(0, 0, 1, 0, t0), bad = id;
    fl_closest r;
    bad.r[0] = 1.1; /* not orthonormal */
    CHECK(fl_sweep_collapse_cursor_closest_posed(c, &bad, q, 0, &r, &err) == FL_ERR_INPUT);
    bad = id;
    bad.t[1] = NAN;
    CHECK(fl_sweep_collapse_cursor_closest_posed(c, &bad, q, 0, &r, &err) == FL_ERR_INPUT);
    bad = id;
    bad.r[4] = INFINITY;
    CHECK(fl_sweep_collapse_cursor_closest_posed(c, &bad, q, 0, &r, &err) == FL_ERR_INPUT);
    double qbad[3] = {0, 1e300, 0};
    CHECK(fl_sweep_collapse_cursor_closest_posed(c, &id, qbad, 0, &r, &err) == FL_ERR_USAGE);
    CHECK(fl_sweep_collapse_cursor_closest_posed(c, NULL, q, 0, &r, &err) == FL_ERR_USAGE);
    CHECK(fl_sweep_collapse_cursor_closest_posed(NULL, &id, q, 0, &r, &err) == FL_ERR_USAGE);
    CHECK(fl_sweep_collapse_cursor_closest_posed(c, &id, q, -1, &r, &err) == FL_ERR_USAGE);
    CHECK_STATUS(fl_sweep_collapse_cursor_closest_posed(c, &id, q, 0, &r, &err), FL_OK, &err);
    check_exact(&m, q, &r);
    fl_sweep_collapse_cursor_free(c);
    fl_sweep_collapse_free(h);
    cm_free(&m);
}

FL_TEST_MAIN(FL_TEST_CASE(test_walks_closed), FL_TEST_CASE(test_walks_open),
             FL_TEST_CASE(test_walks_degenerate), FL_TEST_CASE(test_walks_soup),
             FL_TEST_CASE(test_rigid_closed), FL_TEST_CASE(test_rigid_open_degenerate),
             FL_TEST_CASE(test_reset_matches_fresh), FL_TEST_CASE(test_posed_bad_input))

/* The fixed tables of the edge-collapse hierarchy (Guéziec §4.2, Fig. 5) and its bound
 * invariant. Tables: every split undoes one half-edge collapse u -> v (its added triangles all
 * contain u, its new ones are those not containing v with u replaced by v); every triangle is
 * made and consumed at most once; the split-before dependencies point to later collapses (so
 * the DAG is acyclic), and refining in any order that respects them only ever replaces
 * present triangles and ends at the input mesh; every split's u and v are the collapse's, and
 * its chain successor is a later collapse into v or of v. Bound (collapse_internal.h, the
 * paper's two errors per vertex): in the base mesh and in random partial refinements, every
 * point densely sampled on the input triangles lies within ε = the largest current vertex
 * error at the corners of some present triangle (distances by the independent oracle; the
 * current errors follow the split rule of the paper, restored in the walk's order). */
#include "sweep/collapse_internal.h"
#include "test_collapse_meshes.h"
#include "collapse_cover_check.h"

static int has_vertex(const fl_collapse_tri *t, uint32_t v)
{
    return t->v[0] == v || t->v[1] == v || t->v[2] == v;
}

/* The collapsed vertex u: in every consumed triangle and in no new one. */
static uint32_t split_u(const fl_sweep_collapse *h, uint32_t k)
{
    const fl_collapse_tri *first = h->tri + h->old[h->old_start[k]];
    for (int c = 0; c < 3; c++) {
        uint32_t u = first->v[c];
        int ok = 1;
        for (uint32_t i = h->old_start[k]; i < h->old_start[k + 1]; i++)
            ok &= has_vertex(h->tri + h->old[i], u);
        for (uint32_t t = h->new_start[k]; t < h->new_start[k + 1]; t++)
            ok &= !has_vertex(h->tri + t, u);
        if (ok) return u;
    }
    return FL_COLLAPSE_NONE;
}

/* Whether split k's new triangles are its consumed ones that do not contain v, in order, with
 * u replaced by v. */
static int matches_collapse(const fl_sweep_collapse *h, uint32_t k, uint32_t u, uint32_t v)
{
    uint32_t t = h->new_start[k];
    for (uint32_t i = h->old_start[k]; i < h->old_start[k + 1]; i++) {
        const fl_collapse_tri *o = h->tri + h->old[i];
        if (has_vertex(o, v)) continue;
        if (t >= h->new_start[k + 1]) return 0;
        for (int c = 0; c < 3; c++)
            if (h->tri[t].v[c] != (o->v[c] == u ? v : o->v[c])) return 0;
        t++;
    }
    return t == h->new_start[k + 1];
}

static void check_tables(const fl_sweep_collapse *h)
{
    uint32_t *consumed = calloc(h->tri_count, sizeof *consumed);
    CHECK(h->new_start[0] == h->fine_count);
    CHECK(h->new_start[h->split_count] == h->tri_count);
    for (uint32_t k = 0; k < h->split_count; k++) {
        CHECK(h->old_start[k + 1] > h->old_start[k]);
        CHECK(h->new_start[k + 1] > h->new_start[k]); /* someone owns the fine triangles */
        for (uint32_t i = h->old_start[k]; i < h->old_start[k + 1]; i++) {
            CHECK(h->tri[h->old[i]].destroyer == k);
            consumed[h->old[i]]++;
        }
        for (uint32_t t = h->new_start[k]; t < h->new_start[k + 1]; t++) {
            CHECK(h->tri[t].creator == k);
            uint32_t d = h->tri[t].destroyer; /* split-before edges go to later collapses */
            CHECK(d == FL_COLLAPSE_NONE || d > k);
        }
        uint32_t u = split_u(h, k), n = h->split[k].next;
        CHECK(u != FL_COLLAPSE_NONE);
        CHECK(u == h->split[k].u);
        CHECK(n == FL_COLLAPSE_NONE ||
              (n > k && (h->split[n].v == h->split[k].v || h->split[n].u == h->split[k].v)));
        if (u == FL_COLLAPSE_NONE) continue;
        /* The recorded v replaced u: the new triangles are the consumed ones without v, in
         * order, with u -> v. */
        int found = matches_collapse(h, k, u, h->split[k].v);
        CHECK_MSG(found, "split %u is not the inverse of a half-edge collapse", k);
    }
    for (size_t t = 0; t < h->tri_count; t++)
        CHECK(consumed[t] == (h->tri[t].destroyer != FL_COLLAPSE_NONE));
    free(consumed);
}

static void check_mesh(const fl_mesh *m)
{
    fl_sweep_collapse *h = NULL;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_build(m, NULL, &h, &err), FL_OK, &err);
    if (!h) return;
    check_tables(h);
    uint8_t *done = calloc(h->split_count + 1, 1);
    double *cur = malloc((m->vertex_count + 1) * sizeof *cur);
    memcpy(cur, h->err_self, m->vertex_count * sizeof *cur);
    check_cover(m, h, done, cur); /* the base mesh */
    size_t rounds = 3;
    for (size_t r = 0; r < rounds && h->split_count; r++) {
        for (size_t i = 0; i < 1 + h->split_count / 12; i++)
            run_split(h, done, cur,
                      (uint32_t)(fl_test_rand01(&cm_rng) * (double)h->split_count));
        check_cover(m, h, done, cur);
    }
    for (uint32_t k = 0; k < h->split_count; k++)
        run_split(h, done, cur, k);
    for (size_t v = 0; v < m->vertex_count; v++) /* all split: every error back to 0 */
        CHECK(cur[v] == 0);
    for (uint32_t t = 0; t < h->tri_count; t++) /* fully refined: exactly the input */
        CHECK(fl_collapse_present(h, done, t) == (t < h->fine_count));
    printf("  %zu input triangles, %zu splits, base %zu\n", m->triangle_count, h->split_count,
           h->base_count);
    free(done);
    free(cur);
    fl_sweep_collapse_free(h);
}

static void test_closed(void)
{
    fl_mesh m = cm_noisy_torus(20, 9, 0.15);
    check_mesh(&m);
    cm_free(&m);
}

static void test_open(void)
{
    fl_mesh m = cm_open_grid(12, 0.05);
    check_mesh(&m);
    cm_free(&m);
}

static void test_messy(void)
{
    fl_mesh m = cm_messy(10);
    check_mesh(&m);
    cm_free(&m);
}

FL_TEST_MAIN(FL_TEST_CASE(test_closed), FL_TEST_CASE(test_open), FL_TEST_CASE(test_messy))

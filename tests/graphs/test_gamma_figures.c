/* The sequences of thesis Figures 3.3, 3.4, 3.5 and 3.10 on random sets: each sequence is
 * nested as the thesis states, and each graph is written as an SVG picture (to $FL_FIGURE_DIR
 * when set, which is how docs/img/ is produced, else to the working directory and removed). */
#include "gamma_oracle.h"

typedef struct figure_graph {
    const char *name;
    int range;
    double c[4];
} figure_graph;

static fl_graph draw(const double *p, size_t n, const figure_graph *f)
{
    fl_gamma_params gp = {f->range, {f->c[0], f->c[1], f->c[2], f->c[3]}};
    fl_graph g;
    fl_error err;
    CHECK_STATUS(fl_gamma_graph(p, n, 2, &gp, NULL, &g, &err), FL_OK, &err);
    const char *dir = getenv("FL_FIGURE_DIR");
    char path[512];
    snprintf(path, sizeof path, "%s/%s.svg", dir ? dir : ".", f->name);
    CHECK_STATUS(fl_write_graph(path, p, n, &g, &err), FL_OK, &err);
    if (!dir) remove(path);
    return g;
}

/* Each graph of the list contains the previous one (increasing) or is contained in it. */
static void check_sequence(const double *p, size_t n, const figure_graph *list, size_t count,
                           int increasing)
{
    fl_graph prev = draw(p, n, &list[0]);
    for (size_t i = 1; i < count; i++) {
        fl_graph g = draw(p, n, &list[i]);
        CHECK_MSG(increasing ? oracle_graph_subset(&prev, &g) : oracle_graph_subset(&g, &prev),
                  "%s vs %s", list[i - 1].name, list[i].name);
        fl_graph_free(&prev);
        prev = g;
    }
    fl_graph_free(&prev);
}

/* Fig. 3.3: γ([-1,1],[c,1]) from the hull (c = 1) through the Delaunay triangulation (c = 0)
 * to crossing edges (c < 0), successively containing more edges. */
static void test_figure_3_3_sequence_grows_from_hull_to_delaunay(void)
{
    double *p = oracle_random_points(20, 2, 3300);
    const figure_graph seq[] = {{"fig3_3_a_c1", 1, {-1, 1, 1, 1}},
                                {"fig3_3_b_c0.5", 1, {-1, 1, 0.5, 1}},
                                {"fig3_3_c_c0.2", 1, {-1, 1, 0.2, 1}},
                                {"fig3_3_d_c0", 1, {-1, 1, 0, 1}},
                                {"fig3_3_e_c-0.2", 1, {-1, 1, -0.2, 1}}};
    check_sequence(p, 20, seq, 5, 1);
    free(p);
}

/* Fig. 3.4: β_c-skeletons γ(c,c), c = 0.2, 0.1, 0, -0.2: smaller neighbourhoods, more edges. */
static void test_figure_3_4_beta_skeletons_grow_as_c_decreases(void)
{
    double *p = oracle_random_points(20, 2, 3300);
    const figure_graph seq[] = {{"fig3_4_a_c0.2", 0, {0.2, 0.2}},
                                {"fig3_4_b_c0.1", 0, {0.1, 0.1}},
                                {"fig3_4_c_c0", 0, {0, 0}},
                                {"fig3_4_d_c-0.2", 0, {-0.2, -0.2}}};
    check_sequence(p, 20, seq, 4, 1);
    free(p);
}

/* Fig. 3.5: intersections of discs only. γ([-1,1],[-1,0]) is the complement of the Delaunay
 * triangulation; narrower ranges give subsets of it. */
static void test_figure_3_5_lens_graphs_are_inside_the_delaunay_complement(void)
{
    double *p = oracle_random_points(20, 2, 3300);
    const figure_graph seq[] = {{"fig3_5_a", 1, {-1, 1, -1, 0}},
                                {"fig3_5_c", 1, {-1, 1, -1, -0.9}},
                                {"fig3_5_d", 1, {-1, 1, -1, -0.95}}};
    check_sequence(p, 20, seq, 3, 0);
    fl_graph all = draw(p, 20, &seq[0]),
             quarter = draw(p, 20, &(figure_graph){"fig3_5_b", 1, {-0.25, 0.25, -0.25, 0}});
    fl_graph dt = draw(p, 20, &(figure_graph){"fig3_5_dt", 1, {-1, 1, 0, 1}});
    CHECK(oracle_graph_subset(&quarter, &all));
    CHECK_EQ_INT(all.simplex_count + dt.simplex_count, 20 * 19 / 2); /* complement of DT */
    CHECK_EQ_INT(oracle_graph_subset(&all, &dt), all.simplex_count == 0);
    fl_graph_free(&all);
    fl_graph_free(&quarter);
    fl_graph_free(&dt);
    free(p);
}

/* Fig. 3.10: γ(1/4,1/2) ⊆ γ(-1/4,1/4) ⊆ γ(0,-1/4) ⊆ γ(0,-1/2) on 30 points. */
static void test_figure_3_10_chain_of_lemma_3_3(void)
{
    double *p = oracle_random_points(30, 2, 3310);
    const figure_graph seq[] = {{"fig3_10_a", 0, {0.25, 0.5}},
                                {"fig3_10_b", 0, {-0.25, 0.25}},
                                {"fig3_10_c", 0, {0, -0.25}},
                                {"fig3_10_d", 0, {0, -0.5}}};
    check_sequence(p, 30, seq, 4, 1);
    free(p);
}

FL_TEST_MAIN(FL_TEST_CASE(test_figure_3_3_sequence_grows_from_hull_to_delaunay),
             FL_TEST_CASE(test_figure_3_4_beta_skeletons_grow_as_c_decreases),
             FL_TEST_CASE(test_figure_3_5_lens_graphs_are_inside_the_delaunay_complement),
             FL_TEST_CASE(test_figure_3_10_chain_of_lemma_3_3))

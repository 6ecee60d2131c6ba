/* `flintstone graph` on a set small enough to know every answer by hand. */
#include "cli_run.h"
#include "fl_test.h"

static cli_result r;

/* (0,0), (4,0), (2,1): the angle at (2,1) is obtuse, so the long edge's diametral circle holds
 * (2,1): not a Gabriel edge. The hull and the Delaunay triangulation have all 3 edges; the
 * Gabriel graph, the RNG and the EMST have the 2 short ones. */
static void test_graph_obtuse_triangle_counts(void)
{
    cli_write_file("graph_obtuse.xy", "0 0\n4 0\n2 1\n");
    struct {
        const char *args;
        const char *simplices;
    } cases[] = {
        {"--kind ch", "\"simplices\":3"},
        {"--kind dt", "\"simplices\":3"},
        {"--gamma -1,1", "\"simplices\":3"},
        {"--gamma-range -1,1,0,1", "\"simplices\":3"},
        {"--kind gabriel", "\"simplices\":2"},
        {"--gamma 0,0", "\"simplices\":2"},
        {"--kind rng", "\"simplices\":2"},
        {"--kind emst", "\"simplices\":2"},
        {"--gamma 0,0 --brute-force", "\"simplices\":2"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char args[256];
        snprintf(args, sizeof args, "graph graph_obtuse.xy %s --json", cases[i].args);
        CHECK_EQ_INT(cli_run(&r, args), 0);
        CHECK_MSG(strstr(r.out, cases[i].simplices) != NULL, "%s gave %s", cases[i].args, r.out);
    }
    remove("graph_obtuse.xy");
}

static void test_graph_svg_output_and_usage_errors(void)
{
    cli_write_file("graph_obtuse.xy", "0 0\n4 0\n2 1\n");
    CHECK_EQ_INT(cli_run(&r, "graph graph_obtuse.xy --gamma 0,0 -o graph_out.svg"), 0);
    char svg[4096];
    cli_read_file("graph_out.svg", svg, sizeof svg);
    CHECK(strstr(svg, "<svg") != NULL && strstr(svg, "</svg>") != NULL);
    remove("graph_out.svg");
    CHECK_EQ_INT(cli_run(&r, "graph graph_obtuse.xy"), 1);                       /* no kind */
    CHECK_EQ_INT(cli_run(&r, "graph graph_obtuse.xy --gamma 0,0 --kind dt"), 1); /* two */
    CHECK_EQ_INT(cli_run(&r, "graph graph_obtuse.xy --gamma 2,0"), 1);
    CHECK(strstr(r.err, "c0") != NULL);
    remove("graph_obtuse.xy");
}

FL_TEST_MAIN(FL_TEST_CASE(test_graph_obtuse_triangle_counts),
             FL_TEST_CASE(test_graph_svg_output_and_usage_errors))

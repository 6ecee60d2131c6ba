/* flintstone graph POINTS (--gamma c0,c1 | --gamma-range c0,c1,c2,c3 | --kind K) [-o OUT]
 * The γ-neighbourhood graph (thesis ch. 3) and the classical graphs it unifies. */
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"

static const char *usage_text =
    "usage: flintstone graph POINTS (--gamma c0,c1 | --gamma-range c0,c1,c2,c3 | --kind K)\n"
    "                        [-o OUT] [--brute-force] [--json] [--quiet]\n"
    "\n"
    "Builds a graph on 2D points (edges) or 3D points (triangles).\n"
    "  --gamma c0,c1               the γ-neighbourhood graph γ(c0,c1) (thesis Def. 3.2):\n"
    "                              -1 <= c0, c1 <= 1 and |c0| <= |c1|\n"
    "  --gamma-range c0,c1,c2,c3   γ([c0,c1],[c2,c3]) (Def. 3.3); γ([-1,1],[0,1]) is Delaunay\n"
    "  --kind K                    ch | dt | gabriel | rng | emst | nng | beta-circle:B |\n"
    "                              beta-lune:B | alpha:A\n"
    "  --brute-force               use the O(N^(k+1)) definition (Theorem 3.1), for checking\n"
    "  -o OUT                      .svg (2D picture), .obj or .ply (edges or triangles)\n"
    "  --json                      dim, points, simplices, seconds\n"
    "\n"
    "examples: flintstone graph data/demo/leaf.xy --gamma 0,0 -o gabriel.svg\n"
    "          flintstone graph data/demo/leaf.xy --kind emst --json\n";

typedef struct graph_args {
    const char *input, *gamma, *range, *kind;
    int brute;
} graph_args;

static int parse(int argc, char **argv, cli_common *c, graph_args *a)
{
    for (int i = 1; i < argc; i++) {
        int k = cli_common_option(c, argc, argv, &i);
        if (k < 0) return 1;
        if (k > 0) continue;
        const char **slot = strcmp(argv[i], "--gamma") == 0         ? &a->gamma
                            : strcmp(argv[i], "--gamma-range") == 0 ? &a->range
                            : strcmp(argv[i], "--kind") == 0        ? &a->kind
                                                                    : NULL;
        if (slot) {
            if (i + 1 >= argc) return cli_fail(1, "graph: %s needs a value", argv[i]);
            *slot = argv[++i];
        } else if (strcmp(argv[i], "--brute-force") == 0) {
            a->brute = 1;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            return cli_fail(1, "graph: unknown option '%s' (see flintstone graph --help)", argv[i]);
        } else if (a->input) {
            return cli_fail(1, "graph: one input file, got '%s' and '%s'", a->input, argv[i]);
        } else {
            a->input = argv[i];
        }
    }
    return 0;
}

static fl_status build(const graph_args *a, const fl_points *p, cli_progress *prog, fl_graph *g,
                       fl_error *err)
{
    if (a->kind) {
        fl_graph_kind kind;
        double param = 0;
        fl_status st = fl_graph_kind_parse(a->kind, &kind, &param, err);
        if (st) return st;
        return fl_classic_graph(p->coords, p->count, p->dim, kind, param, g, err);
    }
    fl_gamma_params params;
    fl_status st = fl_gamma_params_parse(a->gamma ? a->gamma : a->range, &params, err);
    if (st) return st;
    fl_graph_options opt = {a->brute ? FL_GAMMA_BRUTE_FORCE : FL_GAMMA_AUTO, 0, cli_progress_fn,
                            prog};
    return fl_gamma_graph(p->coords, p->count, p->dim, &params, &opt, g, err);
}

int cmd_graph(int argc, char **argv)
{
    cli_common c = {0};
    graph_args a = {0};
    if (parse(argc, argv, &c, &a)) return 1;
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    if (!a.input) return cli_fail(1, "graph: no input file (see flintstone graph --help)");
    if ((a.gamma != NULL) + (a.range != NULL) + (a.kind != NULL) != 1)
        return cli_fail(1, "graph: give exactly one of --gamma, --gamma-range, --kind");
    fl_error err;
    fl_points p;
    double t0 = cli_now();
    if (fl_read_points(a.input, &p, &err)) return cli_report(&err);
    int code = cli_check_output(c.output, p.dim == 2 ? "svg obj ply" : "obj ply");
    if (code) {
        fl_points_free(&p);
        return code;
    }
    cli_progress prog;
    cli_progress_init(&prog, &c);
    fl_graph g = {0};
    fl_status st = build(&a, &p, &prog, &g, &err);
    cli_progress_done(&prog);
    if (st == FL_OK && c.output) st = fl_write_graph(c.output, p.coords, p.count, &g, &err);
    double seconds = cli_now() - t0;
    if (st) {
        fl_graph_free(&g);
        fl_points_free(&p);
        return cli_report(&err);
    }
    if (c.json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_int(&j, "dim", p.dim);
        cli_json_uint(&j, "points", p.count);
        cli_json_uint(&j, "simplices", g.simplex_count);
        cli_json_double(&j, "seconds", seconds);
        cli_json_end(&j);
    } else if (!c.quiet) {
        printf("%dD graph on %zu points: %zu %s (%.3f s)\n", p.dim, p.count, g.simplex_count,
               g.simplex_size == 2 ? "edges" : "triangles", seconds);
    }
    fl_graph_free(&g);
    fl_points_free(&p);
    return 0;
}

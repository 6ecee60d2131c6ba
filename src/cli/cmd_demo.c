/* flintstone demo and flintstone report: the whole pipeline (src/cli/pipeline*.c) on the
 * bundled default inputs (data/demo, our own synthetic shapes with their ground truth) or on
 * the user's own points or mesh. Both write report.html (one static page: pictures, numbers,
 * reproducing commands) and summary.json into the output directory, each atomically. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "cli/pipeline.h"
#include "core/core.h"

#ifndef FL_DATA_DIR
#define FL_DATA_DIR "data/demo"
#endif

static const char *demo_usage =
    "usage: flintstone demo [--data DIR] [--out DIR] [--json] [--quiet]\n"
    "\n"
    "Runs the whole pipeline on the bundled inputs and writes report.html, summary.json and\n"
    "every output into the output directory:\n"
    "  leaf    160 points on a closed 2D curve -> Delaunay -> boundary polygon -> flintstone\n"
    "          approximations -> point inclusion -> distance to the true curve\n"
    "  peanut  1500 points on a closed surface -> closed genus-0 surface -> check -> distance\n"
    "          to the true surface\n"
    "  torus   a closed genus-1 mesh -> check\n"
    "\n"
    "  --data DIR  where the bundled inputs are (default: the source tree's data/demo, then\n"
    "              ./data/demo)\n"
    "  --out DIR   output directory (default: demo-out)\n"
    "\n"
    "example: flintstone demo --out /tmp/demo && xdg-open /tmp/demo/report.html\n";

static const char *report_usage =
    "usage: flintstone report INPUT [--truth REFERENCE] [--out DIR] [--json] [--quiet]\n"
    "\n"
    "Runs the pipeline of `flintstone demo` on your own data and writes report.html and\n"
    "summary.json into the output directory. INPUT is 2D points (.xy, ...), 3D points (.xyz,\n"
    "...) or a mesh (.off .obj .ply .stl; reconstruction is then skipped). --truth gives the\n"
    "curve (ordered closed polyline, 2D) or surface (mesh, 3D) the points came from, for the\n"
    "distance check.\n"
    "\n"
    "  --out DIR   output directory (default: report-out)\n"
    "\n"
    "example: flintstone report scan.xyz --out scan-report\n";

typedef struct run {
    const char *data_dir, *out_dir, *input, *truth;
    int report; /* 1: `report INPUT`, 0: `demo` */
} run;

static const char *find_data_dir(void)
{
    struct stat st;
    if (stat(FL_DATA_DIR "/torus.off", &st) == 0) return FL_DATA_DIR;
    return "data/demo";
}

static int parse_args(int argc, char **argv, cli_common *c, run *r)
{
    for (int i = 1; i < argc; i++) {
        int k = cli_common_option(c, argc, argv, &i);
        if (k < 0) return 1;
        if (k > 0) continue;
        const char *opt = argv[i];
        int takes = strcmp(opt, "--out") == 0 || (!r->report && strcmp(opt, "--data") == 0) ||
                    (r->report && strcmp(opt, "--truth") == 0);
        if (takes && i + 1 >= argc) return cli_fail(1, "%s: %s needs a value", argv[0], opt);
        if (strcmp(opt, "--out") == 0)
            r->out_dir = argv[++i];
        else if (takes && !r->report)
            r->data_dir = argv[++i];
        else if (takes)
            r->truth = argv[++i];
        else if (r->report && opt[0] != '-' && !r->input)
            r->input = opt;
        else
            return cli_fail(1, "%s: unexpected argument '%s' (see flintstone %s --help)",
                            argv[0], opt, argv[0]);
    }
    if (c->output) r->out_dir = c->output;
    if (r->report && !c->help && !r->input)
        return cli_fail(1, "report: which input? (see flintstone report --help)");
    return 0;
}

/* Every input must be readable before anything is written. */
static int check_readable(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return cli_fail(4, "cannot open '%s': %s", path, strerror(errno));
    fclose(f);
    return 0;
}

static void data_path(const run *r, char *buf, size_t size, const char *name)
{
    snprintf(buf, size, "%s/%s", r->data_dir, name);
}

/* The input's dimension decides the pipeline: a mesh or 3D points go to the 3D one. */
static int input_dim(const char *path)
{
    fl_error err;
    fl_mesh m;
    if (fl_read_mesh(path, &m, &err) == FL_OK) {
        int has_faces = m.triangle_count > 0;
        fl_mesh_free(&m);
        if (has_faces) return 3;
    }
    fl_points p = {0};
    int dim = fl_read_points(path, &p, &err) == FL_OK ? p.dim : 0;
    fl_points_free(&p);
    return dim;
}

static int run_pipeline(const run *r, pipeline *pl)
{
    if (r->report) {
        const char *base = strrchr(r->input, '/');
        base = base ? base + 1 : r->input;
        char name[128];
        snprintf(name, sizeof name, "%.*s", (int)strcspn(base, "."), base);
        if (!name[0]) snprintf(name, sizeof name, "input");
        if (input_dim(r->input) == 2)
            pl_run_2d(pl, name, r->input, r->truth);
        else
            pl_run_3d(pl, name, r->input, r->truth);
        return 0;
    }
    char leaf[1024], leaf_truth[1024], peanut[1024], peanut_truth[1024], torus[1024];
    data_path(r, leaf, sizeof leaf, "leaf.xy");
    data_path(r, leaf_truth, sizeof leaf_truth, "leaf-truth.xy");
    data_path(r, peanut, sizeof peanut, "peanut.xyz");
    data_path(r, peanut_truth, sizeof peanut_truth, "peanut-truth.off");
    data_path(r, torus, sizeof torus, "torus.off");
    pl_run_2d(pl, "leaf", leaf, leaf_truth);
    pl_run_3d(pl, "peanut", peanut, peanut_truth);
    pl_run_3d(pl, "torus", torus, NULL);
    return 0;
}

static int preflight(const run *r)
{
    if (r->report) {
        if (check_readable(r->input)) return 4;
        return r->truth ? check_readable(r->truth) : 0;
    }
    static const char *files[] = {"leaf.xy", "leaf-truth.xy", "peanut.xyz", "peanut-truth.off",
                                  "torus.off"};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        char p[1024];
        data_path(r, p, sizeof p, files[i]);
        if (check_readable(p)) return 4;
    }
    return 0;
}

static int run_main(int argc, char **argv, run *r, const char *usage)
{
    cli_common c = {0};
    if (parse_args(argc, argv, &c, r)) return 1;
    if (c.help) {
        fputs(usage, stdout);
        return 0;
    }
    int code = preflight(r);
    if (code) return code;
    if (mkdir(r->out_dir, 0777) != 0 && errno != EEXIST)
        return cli_fail(4, "%s: cannot create output directory '%s': %s", argv[0], r->out_dir,
                        strerror(errno));
    char summary[1024], html[1024];
    snprintf(summary, sizeof summary, "%s/summary.json", r->out_dir);
    snprintf(html, sizeof html, "%s/report.html", r->out_dir);
    fl_error err;
    fl_out_file out;
    if (fl_out_open(&out, summary, 0, &err)) return cli_report(&err);
    cli_json json;
    pipeline pl = {r->out_dir, &json, NULL, c.quiet || c.json, 0, 0};
    pl.page = cli_page_new(r->report ? "flintstone report" : "flintstone demo",
                           "Closed object boundaries from scattered points, and what one does "
                           "with them. Every step below shows its picture, its key numbers and "
                           "the command that reproduces it.");
    if (!pl.page) {
        fl_out_abort(&out);
        cli_fail(3, "out of memory");
        cli_memory_limit_note();
        return 3;
    }
    double t0 = cli_now();
    cli_json_begin(&json, out.fp);
    cli_json_string(&json, "flintstone", fl_version());
    cli_json_string(&json, "report", "report.html");
    run_pipeline(r, &pl);
    cli_json_double(&json, "seconds", cli_now() - t0);
    cli_json_end(&json);
    fl_status st = fl_out_commit(&out, &err);
    if (st == FL_OK) st = cli_page_write(pl.page, html, &err);
    cli_page_free(pl.page);
    if (st) return cli_report(&err);
    if (c.json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_string(&j, "summary", summary);
        cli_json_string(&j, "report", html);
        cli_json_bool(&j, "ok", pl.failed == 0);
        cli_json_double(&j, "seconds", cli_now() - t0);
        cli_json_end(&j);
    } else if (!c.quiet) {
        printf("%s in %.2f s; open %s (numbers in %s)\n",
               pl.failed ? "finished WITH ERRORS" : "done", cli_now() - t0, html, summary);
    }
    return pl.failed;
}

int cmd_demo(int argc, char **argv)
{
    run r = {find_data_dir(), "demo-out", NULL, NULL, 0};
    return run_main(argc, argv, &r, demo_usage);
}

int cmd_report(int argc, char **argv)
{
    run r = {NULL, "report-out", NULL, NULL, 1};
    return run_main(argc, argv, &r, report_usage);
}

/* flintstone hausdorff A B [--precision P | --relative R] [--budget S] [--both] [--closed]
 *                      [--field a|b] [-o FIELD.ply] [--json]
 * Certified Hausdorff distance between two meshes or two polylines (Guéziec §6), through the
 * Meshsweeper closest-point cursor. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

static const char *usage_text =
    "usage: flintstone hausdorff A B [--precision P | --relative R] [--budget SECONDS] [--both]\n"
    "                            [--closed] [--field a|b] [-o FIELD.ply] [--json] [--quiet]\n"
    "\n"
    "Hausdorff distance between A and B over every point of their surfaces, as certified\n"
    "intervals [lower, upper]: lower is a distance measured at a sample point, upper is proven\n"
    "for every point. A and B are triangle meshes (.off .obj .ply .stl) or both polylines (point\n"
    "files in order: .xy .xyz .csv .txt; --closed joins the last point to the first).\n"
    "\n"
    "  --precision P  stop when upper - lower <= P (a length)\n"
    "  --relative R   the same with P = R x bounding-box diagonal (default 1e-3)\n"
    "  --budget S     stop after about S seconds with the best intervals so far\n"
    "  --both         refine both directed distances to the precision (by default the\n"
    "                 direction that cannot hold the maximum keeps a wider interval)\n"
    "  --field a|b    which shape's distance field -o writes (default: where the maximum is)\n"
    "  -o FIELD.ply   the refined samples with per-vertex distance (quality) and colour,\n"
    "                 blue = 0 to red = the Hausdorff distance\n"
    "  --json         h_ab, h_ba, hausdorff ([lower, upper] each), where, samples, seconds, ...\n"
    "\n"
    "example: flintstone hausdorff original.off simplified.off --relative 1e-4 -o field.ply "
    "--json\n";

typedef struct hausdorff_args {
    const char *a, *b;
    fl_hausdorff_options opt;
    int closed, field; /* field: -1 dominant, 0 a, 1 b */
} hausdorff_args;

static int parse_value(const char *o, const char *v, hausdorff_args *a)
{
    double x;
    if (!strcmp(o, "--field")) {
        if (strcmp(v, "a") && strcmp(v, "b")) return cli_fail(1, "hausdorff: --field takes a or b");
        a->field = v[0] == 'b';
        return 0;
    }
    if (cli_parse_double(v, &x) || !(x >= 0) || isinf(x))
        return cli_fail(1, "hausdorff: %s takes a number >= 0", o);
    if (!strcmp(o, "--precision")) a->opt.precision = x;
    if (!strcmp(o, "--relative")) a->opt.relative = x;
    if (!strcmp(o, "--budget")) a->opt.budget_seconds = x;
    return 0;
}

static int parse(int argc, char **argv, cli_common *c, hausdorff_args *a)
{
    a->field = -1;
    for (int i = 1; i < argc; i++) {
        int r = cli_common_option(c, argc, argv, &i);
        if (r < 0) return 1;
        if (r > 0) continue;
        const char *o = argv[i];
        if (!strcmp(o, "--precision") || !strcmp(o, "--relative") || !strcmp(o, "--budget") ||
            !strcmp(o, "--field")) {
            if (i + 1 >= argc) return cli_fail(1, "hausdorff: %s needs a value", o);
            if (parse_value(o, argv[++i], a)) return 1;
        } else if (!strcmp(o, "--both")) {
            a->opt.both_directions = 1;
        } else if (!strcmp(o, "--closed")) {
            a->closed = 1;
        } else if (o[0] == '-' && o[1]) {
            return cli_fail(1, "hausdorff: unknown option '%s' (see --help)", o);
        } else if (!a->a) {
            a->a = o;
        } else if (!a->b) {
            a->b = o;
        } else {
            return cli_fail(1, "hausdorff: too many arguments ('%s')", o);
        }
    }
    if (a->opt.precision > 0 && a->opt.relative > 0)
        return cli_fail(1, "hausdorff: give --precision or --relative, not both");
    return 0;
}

static int is_mesh_file(const char *path)
{
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    return !strcmp(ext, "off") || !strcmp(ext, "obj") || !strcmp(ext, "ply") || !strcmp(ext, "stl");
}

static fl_status run_meshes(const hausdorff_args *a, fl_hausdorff_result *r, fl_error *err)
{
    fl_mesh ma = {0}, mb = {0};
    fl_status st = fl_read_mesh(a->a, &ma, err);
    if (st == FL_OK) st = fl_read_mesh(a->b, &mb, err);
    if (st == FL_OK) st = fl_hausdorff_meshes(&ma, &mb, &a->opt, r, err);
    fl_mesh_free(&ma);
    fl_mesh_free(&mb);
    return st;
}

static fl_status run_polylines(const hausdorff_args *a, fl_hausdorff_result *r, fl_error *err)
{
    fl_points pa = {0}, pb = {0};
    fl_status st = fl_read_points(a->a, &pa, err);
    if (st == FL_OK) st = fl_read_points(a->b, &pb, err);
    if (st == FL_OK && pa.dim != pb.dim)
        st = fl_fail(err, FL_ERR_INPUT, a->b, -1, "polylines of different dimensions (%dD, %dD)",
                     pa.dim, pb.dim);
    if (st == FL_OK)
        st = fl_hausdorff_polylines(pa.coords, pa.count, a->closed, pb.coords, pb.count, a->closed,
                                    pa.dim, &a->opt, r, err);
    fl_points_free(&pa);
    fl_points_free(&pb);
    return st;
}

static void json_interval(cli_json *j, const char *key, const double *iv)
{
    cli_json_open_array(j, key);
    cli_json_double(j, NULL, iv[0]);
    cli_json_double(j, NULL, iv[1]);
    cli_json_close(j);
}

static void print_json(const fl_hausdorff_result *r, double seconds)
{
    cli_json j;
    cli_json_begin(&j, stdout);
    json_interval(&j, "h_ab", r->h_ab);
    json_interval(&j, "h_ba", r->h_ba);
    json_interval(&j, "hausdorff", r->hausdorff);
    cli_json_open_array(&j, "where");
    for (int k = 0; k < 2; k++) {
        cli_json_open_array(&j, NULL);
        for (int x = 0; x < 3; x++)
            cli_json_double(&j, NULL, r->where[k][x]);
        cli_json_close(&j);
    }
    cli_json_close(&j);
    cli_json_string(&j, "where_on", r->where_on_b ? "b" : "a");
    cli_json_uint(&j, "samples", r->samples);
    cli_json_double(&j, "precision", r->precision);
    cli_json_double(&j, "reached", r->reached);
    cli_json_bool(&j, "budget_exhausted", r->budget_exhausted);
    cli_json_double(&j, "seconds", seconds);
    cli_json_end(&j);
}

int cmd_hausdorff(int argc, char **argv)
{
    cli_common c = {0};
    hausdorff_args a = {0};
    if (parse(argc, argv, &c, &a)) return 1;
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    if (!a.b) return cli_fail(1, "hausdorff: needs two shapes A and B (see --help)");
    if (is_mesh_file(a.a) != is_mesh_file(a.b))
        return cli_fail(1, "hausdorff: A and B must both be meshes or both polylines");
    if (c.output) {
        char ext[16];
        fl_path_extension(c.output, ext, sizeof ext);
        if (strcmp(ext, "ply")) return cli_fail(1, "hausdorff: -o writes a .ply distance field");
        a.opt.keep_field = 1;
    }
    cli_progress prog;
    cli_progress_init(&prog, &c);
    a.opt.progress = cli_progress_fn;
    a.opt.progress_user = &prog;
    double t0 = cli_now();
    fl_error err;
    fl_hausdorff_result r;
    fl_status st = is_mesh_file(a.a) ? run_meshes(&a, &r, &err) : run_polylines(&a, &r, &err);
    cli_progress_done(&prog);
    if (st == FL_OK && c.output) {
        int on_b = a.field < 0 ? r.where_on_b : a.field;
        st = fl_hausdorff_write_field_ply(c.output, on_b ? &r.field_ba : &r.field_ab, 0,
                                          r.hausdorff[1], &err);
    }
    if (st == FL_OK) {
        if (c.json) {
            print_json(&r, cli_now() - t0);
        } else if (!c.quiet) {
            printf("hausdorff in [%.9g, %.9g] (h_ab [%.9g, %.9g], h_ba [%.9g, %.9g]), %zu samples"
                   "%s (%.3f s)\n",
                   r.hausdorff[0], r.hausdorff[1], r.h_ab[0], r.h_ab[1], r.h_ba[0], r.h_ba[1],
                   r.samples, r.budget_exhausted ? ", budget exhausted" : "", cli_now() - t0);
        }
    }
    if (st == FL_OK) fl_hausdorff_result_free(&r);
    return st ? cli_report(&err) : 0;
}

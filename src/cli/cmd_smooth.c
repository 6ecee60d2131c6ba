/* flintstone smooth POLYGON|MESH ... — G1 cubic Bézier curves and surfaces through the
 * vertices (thesis ch. 9; docs/smooth.md). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

static const char *usage_text =
    "usage: flintstone smooth POLYGON [-o OUT.svg|.xy] [--tangents length|uniform|inverse]\n"
    "                         [--samples N] [--json] [--quiet]\n"
    "       flintstone smooth MESH [--scheme three-split|six-split|two-split|pn|auto] [--tess N]\n"
    "                         [--normals area|uniform|inverse] [--tension B] [--samples N]\n"
    "                         [-o OUT.off|.ply|.obj|.stl|.bez] [--json] [--quiet]\n"
    "\n"
    "A tangent-continuous (G1) boundary through every vertex (Veltkamp's thesis ch. 9).\n"
    "POLYGON (.xy .geojson .json): closed cubic Bézier curves (§9.2); -o .svg writes the\n"
    "Bézier paths, -o .xy the curve sampled N points a segment (--samples, default 16).\n"
    "MESH (.off .obj .ply .stl, closed, manifold, oriented): cubic Bézier triangles\n"
    "interpolating the vertices and estimated normals (§9.4). Schemes: auto (default: per\n"
    "connected component both splits below, keeping the G1 one, the nearer if both are),\n"
    "three-split (§9.6, G1 on most meshes, smooth reflection lines), six-split (§9.8, G1\n"
    "on every mesh tested, smaller deviation on rough meshes, wigglier reflection lines on\n"
    "smooth ones), pn (the macro patches of steps 1-3 = PN triangles, only C0), two-split\n"
    "(§9.7: pairs of thin triangles split in two at their common edge as one C1 cross\n"
    "split, the rest three-split; G1).\n"
    "\n"
    "  --tangents W   curve tangent weighting (default length, §9.2 method 1)\n"
    "  --normals W    surface normal weighting (default area, §9.4 method 1)\n"
    "  --tension B    step 2 fraction of the projected edge, 0 < B < 1 (default 1/3)\n"
    "  --tess N       mesh output: N segments a patch edge (default 4)\n"
    "  --samples N    measuring: points a patch edge (default 8) / curve samples (16)\n"
    "  -o OUT         .off .obj .ply .stl: the tessellated watertight mesh; .bez: the\n"
    "                 Bézier control nets (docs/formats.md)\n"
    "  --json         mesh: patches, max_vertex_error, max_normal_error,\n"
    "                 max_edge_normal_jump_deg, orientation_repairs, orientation_flips,\n"
    "                 max_deviation (relative to the mean edge length), quadratic_edges,\n"
    "                 two_split_pairs, singular_edges, six_split_triangles,\n"
    "                 seconds; polygon: segments, orientation_repairs, max_tangent_jump_deg,\n"
    "                 seconds\n"
    "\n"
    "example: flintstone smooth torus.off --tess 6 -o smooth.off --json\n";

typedef struct smooth_args {
    const char *input, *scheme;
    int weighting, weighting_set;
    double tension;
    size_t tess, samples;
} smooth_args;

static int parse_weighting(const char *s, int surface, int *out)
{
    if (!strcmp(s, surface ? "area" : "length"))
        *out = FL_G1_WEIGHT_SIZE;
    else if (!strcmp(s, "uniform"))
        *out = FL_G1_WEIGHT_UNIFORM;
    else if (!strcmp(s, "inverse"))
        *out = FL_G1_WEIGHT_INVERSE;
    else
        return -1;
    return 0;
}

static int parse_value(smooth_args *a, const char *o, const char *v)
{
    if (!strcmp(o, "--tangents") || !strcmp(o, "--normals")) {
        if (parse_weighting(v, !strcmp(o, "--normals"), &a->weighting))
            return cli_fail(1, "smooth: %s takes %s, uniform or inverse", o,
                            strcmp(o, "--normals") ? "length" : "area");
        a->weighting_set = 1;
    } else if (!strcmp(o, "--scheme")) {
        if (strcmp(v, "three-split") && strcmp(v, "six-split") && strcmp(v, "two-split") &&
            strcmp(v, "auto") && strcmp(v, "pn"))
            return cli_fail(1,
                            "smooth: --scheme takes three-split, six-split, two-split, pn or auto");
        a->scheme = v;
    } else if (!strcmp(o, "--tension")) {
        if (cli_parse_double(v, &a->tension) || !(a->tension > 0 && a->tension < 1))
            return cli_fail(1, "smooth: --tension takes a number in (0, 1)");
    } else if (!strcmp(o, "--tess")) {
        if (cli_parse_size(v, &a->tess) || a->tess == 0 || a->tess > 4096)
            return cli_fail(1, "smooth: --tess takes a whole number in 1..4096");
    } else if (cli_parse_size(v, &a->samples) || a->samples < 2 || a->samples > 10000) {
        return cli_fail(1, "smooth: --samples takes a whole number in 2..10000");
    }
    return 0;
}

static int parse(int argc, char **argv, cli_common *c, smooth_args *a)
{
    static const char *valued[] = {"--tangents", "--normals", "--scheme",
                                   "--tension",  "--tess",    "--samples"};
    for (int i = 1; i < argc; i++) {
        int r = cli_common_option(c, argc, argv, &i);
        if (r < 0) return 1;
        if (r > 0) continue;
        const char *o = argv[i];
        int is_valued = 0;
        for (size_t k = 0; k < sizeof valued / sizeof *valued; k++)
            is_valued |= !strcmp(o, valued[k]);
        if (is_valued) {
            if (i + 1 >= argc) return cli_fail(1, "smooth: %s needs a value", o);
            if (parse_value(a, o, argv[++i])) return 1;
        } else if (o[0] == '-' && o[1]) {
            return cli_fail(1, "smooth: unknown option '%s' (see --help)", o);
        } else if (!a->input) {
            a->input = o;
        } else {
            return cli_fail(1, "smooth: too many arguments ('%s')", o);
        }
    }
    return 0;
}

static int is_polygon_file(const char *path)
{
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    return !strcmp(ext, "xy") || !strcmp(ext, "geojson") || !strcmp(ext, "json");
}

/* The largest angle between P'(1) and Q'(0) over all joints (0 for a G1 curve). */
static double max_tangent_jump(const fl_g1_curve *c)
{
    double worst = 0;
    for (size_t r = 0; r < c->ring_count; r++)
        for (size_t i = c->ring_start[r]; i < c->ring_start[r + 1]; i++) {
            size_t prev = i > c->ring_start[r] ? i - 1 : c->ring_start[r + 1] - 1;
            double a[2], b[2];
            fl_g1_curve_eval(c, prev, 1, NULL, a);
            fl_g1_curve_eval(c, i, 0, NULL, b);
            double ang = atan2(fabs(a[0] * b[1] - a[1] * b[0]), a[0] * b[0] + a[1] * b[1]);
            worst = fmax(worst, ang * (180 / 3.14159265358979323846));
        }
    return worst;
}

static fl_status write_curve(const char *path, const fl_g1_curve *c, size_t samples, fl_error *err)
{
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    if (!strcmp(ext, "svg")) return fl_g1_curve_write_svg(path, c, err);
    fl_polygon s;
    fl_status st = fl_g1_curve_sample(c, samples, &s, err);
    if (!st) st = fl_write_polygon(path, &s, err);
    fl_polygon_free(&s);
    return st;
}

static int run_curve(const cli_common *c, const smooth_args *a)
{
    double t0 = cli_now();
    fl_error err;
    fl_polygon p;
    fl_g1_curve curve = {0};
    fl_status st = fl_read_polygon(a->input, &p, &err);
    if (st) return cli_report(&err);
    fl_g1_curve_options o = {.weighting = a->weighting, .tension = a->tension};
    st = fl_g1_curve_build(&p, &o, &curve, &err);
    if (!st && c->output) st = write_curve(c->output, &curve, a->samples ? a->samples : 16, &err);
    if (!st) {
        double jump = max_tangent_jump(&curve);
        if (c->json) {
            cli_json j;
            cli_json_begin(&j, stdout);
            cli_json_uint(&j, "segments", curve.vertex_count);
            cli_json_uint(&j, "rings", curve.ring_count);
            cli_json_uint(&j, "orientation_repairs", curve.orientation_repairs);
            cli_json_double(&j, "max_tangent_jump_deg", jump);
            cli_json_double(&j, "seconds", cli_now() - t0);
            cli_json_end(&j);
        } else if (!c->quiet) {
            printf("%zu cubic segments in %zu rings, %zu tangents repaired, max tangent jump "
                   "%.3g deg (%.3f s)\n",
                   curve.vertex_count, curve.ring_count, curve.orientation_repairs, jump,
                   cli_now() - t0);
        }
    }
    fl_g1_curve_free(&curve);
    fl_polygon_free(&p);
    return st ? cli_report(&err) : 0;
}

static fl_status write_surface(const char *path, const fl_g1_surface *s, size_t tess, fl_error *err)
{
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    if (!strcmp(ext, "bez")) return fl_g1_write_bez(path, s, err);
    fl_mesh tm;
    double *normals = NULL;
    fl_status st = fl_g1_surface_tessellate(s, (unsigned)tess, &tm, &normals, err);
    if (!st) st = fl_write_mesh(path, &tm, err);
    free(normals);
    fl_mesh_free(&tm);
    return st;
}

static void print_surface(const cli_common *c, const fl_g1_surface *s, const fl_g1_metrics *m,
                          double seconds)
{
    if (c->json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_uint(&j, "patches", s->patch_count);
        cli_json_double(&j, "max_vertex_error", m->max_vertex_error);
        cli_json_double(&j, "max_normal_error", m->max_normal_error);
        cli_json_double(&j, "max_edge_normal_jump_deg", m->max_edge_normal_jump_deg);
        cli_json_uint(&j, "orientation_repairs", s->orientation_repairs);
        cli_json_uint(&j, "orientation_failures", s->orientation_failures);
        cli_json_uint(&j, "orientation_flips", m->orientation_flips);
        cli_json_double(&j, "max_deviation", m->max_deviation);
        cli_json_uint(&j, "quadratic_edges", s->quadratic_edges);
        cli_json_uint(&j, "two_split_pairs", s->two_split_pairs);
        cli_json_uint(&j, "singular_edges", s->singular_edges);
        cli_json_uint(&j, "six_split_triangles", s->six_split_triangles);
        cli_json_double(&j, "seconds", seconds);
        cli_json_end(&j);
    } else if (!c->quiet) {
        printf("%zu cubic patches: vertex error %.3g, normal error %.3g, max normal jump %.3g deg"
               " across patch edges, %zu normals repaired, %zu folded edges, max deviation "
               "%.4g mean edge lengths (%.3f s)\n",
               s->patch_count, m->max_vertex_error, m->max_normal_error,
               m->max_edge_normal_jump_deg, s->orientation_repairs, m->orientation_flips,
               m->max_deviation, seconds);
    }
}

static int run_surface(const cli_common *c, const smooth_args *a)
{
    double t0 = cli_now();
    fl_error err;
    fl_mesh m;
    fl_g1_surface s = {0};
    fl_g1_metrics metrics;
    fl_status st = fl_read_mesh(a->input, &m, &err);
    if (st) return cli_report(&err);
    /* auto (the default): per connected component the three-split and the six-split, the G1
     * one kept, the one nearer the mesh if both are (docs/smooth.md, "Auto") */
    int scheme = FL_G1_AUTO;
    if (a->scheme && !strcmp(a->scheme, "three-split")) scheme = FL_G1_THREE_SPLIT;
    if (a->scheme && !strcmp(a->scheme, "pn")) scheme = FL_G1_MACRO;
    if (a->scheme && !strcmp(a->scheme, "six-split")) scheme = FL_G1_SIX_SPLIT;
    if (a->scheme && !strcmp(a->scheme, "two-split")) scheme = FL_G1_TWO_SPLIT;
    fl_g1_surface_options o = {.scheme = scheme,
                               .weighting = a->weighting,
                               .tension = a->tension};
    st = fl_g1_surface_build(&m, &o, &s, &err);
    if (!st)
        st = fl_g1_surface_measure(&s, &m, a->samples ? (unsigned)a->samples : 8, &metrics, &err);
    if (!st && c->output) st = write_surface(c->output, &s, a->tess ? a->tess : 4, &err);
    if (!st) print_surface(c, &s, &metrics, cli_now() - t0);
    fl_g1_surface_free(&s);
    fl_mesh_free(&m);
    return st ? cli_report(&err) : 0;
}

int cmd_smooth(int argc, char **argv)
{
    cli_common c = {0};
    smooth_args a = {0};
    if (parse(argc, argv, &c, &a)) return 1;
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    if (!a.input) return cli_fail(1, "smooth: needs a POLYGON or MESH file (see --help)");
    int code = cli_check_output(c.output, is_polygon_file(a.input) ? "svg xy geojson json"
                                                                   : "off obj ply stl bez");
    if (code) return code;
    if (is_polygon_file(a.input)) {
        if (a.scheme || a.tess)
            return cli_fail(1, "smooth: --scheme and --tess apply to meshes, not polygons");
        return run_curve(&c, &a);
    }
    return run_surface(&c, &a);
}

/* flintstone render INPUT [-o OUT.png|OUT.svg] [--view A,E] [--size WxH] ...
 * Pictures of inputs and results: 3D meshes, balls and 3D points through the library's
 * software rasterizer into a PNG (encoded with libpng, src/cli/png_write.c); 2D points and
 * polygons through the library's SVG canvas. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "cli/png_write.h"
#include "core/core.h"

static const char *usage_text =
    "usage: flintstone render INPUT [-o OUT.png|OUT.svg] [options] [--json] [--quiet]\n"
    "\n"
    "Draws INPUT. By its type:\n"
    "  mesh (.off .obj .ply .stl)      -> PNG: z-buffered, shaded, optional wireframe/zebra\n"
    "  balls (.xyzw: x y z r^2)        -> PNG: ray-cast shaded spheres\n"
    "  3D points (.xyz ..., or a mesh file without faces) -> PNG: small spheres\n"
    "  2D points (.xy .csv .txt)       -> SVG: dots (--closed: a closed polyline, --polygon:\n"
    "                                     read as rings, --graph KIND: a graph of the points)\n"
    "  polygons (.geojson .json)       -> SVG: filled rings, holes empty\n"
    "The output defaults to INPUT's name with .png or .svg, in the current directory.\n"
    "\n"
    "PNG options:\n"
    "  --view A,E        camera azimuth and elevation in degrees (default 30,20)\n"
    "  --size WxH        image size in pixels (default 800x600); for SVG the longer side\n"
    "  --ortho           orthographic instead of perspective projection\n"
    "  --fov DEG         perspective field of view (default 30)\n"
    "  --aa              2x2 supersampling (anti-aliasing)\n"
    "  --flat            face normals (default for meshes: smooth vertex normals)\n"
    "  --wireframe       dark triangle edges on top\n"
    "  --zebra [--stripes N]  reflection lines for smoothness checks (default 10 stripes)\n"
    "  --field FILE      one number per vertex (whitespace separated, '#' comments), coloured\n"
    "                    by --colormap coolwarm|viridis|gray over --range MIN,MAX (default:\n"
    "                    the values' range)\n"
    "  --background C    #rrggbb, #rrggbbaa or transparent (default white)\n"
    "  --radius R        sphere radius for 3D points (default 0.4% of the diagonal)\n"
    "  --json            kind, output, width, height, pixels_covered (null for SVG),\n"
    "                    elements (SVG shapes), seconds\n"
    "\n"
    "examples: flintstone render data/demo/torus.off -o torus.png --view 30,35 --wireframe\n"
    "          flintstone render shape.off --field distance.txt --aa -o distance.png\n"
    "          flintstone render data/demo/leaf.xy --graph emst -o leaf.svg\n";

typedef struct render_args {
    const char *input, *field, *graph;
    double azimuth, elevation, fov, radius, range[2];
    uint32_t width, height;
    int ortho, aa, flat, wireframe, zebra, has_range, closed, polygon, transparent;
    double stripes;
    fl_render_colormap colormap;
    uint8_t background[4];
} render_args;

static int parse_pair(const char *s, char sep, double *a, double *b)
{
    char buf[128];
    const char *mid = strchr(s, sep);
    if (!mid || (size_t)(mid - s) >= sizeof buf) return -1;
    memcpy(buf, s, (size_t)(mid - s));
    buf[mid - s] = '\0';
    return cli_parse_double(buf, a) || cli_parse_double(mid + 1, b) ? -1 : 0;
}

static int parse_color(const char *s, uint8_t rgba[4])
{
    if (!strcmp(s, "transparent")) {
        memset(rgba, 0, 4);
        return 0;
    }
    size_t n = strlen(s);
    if (s[0] != '#' || (n != 7 && n != 9)) return -1;
    rgba[3] = 255;
    for (size_t i = 0; i + 1 < n; i += 2) {
        char hex[3] = {s[1 + i], s[2 + i], 0}, *end;
        unsigned long v = strtoul(hex, &end, 16);
        if (*end) return -1;
        rgba[i / 2] = (uint8_t)v;
    }
    return 0;
}

static int parse_value(render_args *a, const char *o, const char *v)
{
    double w, h;
    if (!strcmp(o, "--view")) {
        if (parse_pair(v, ',', &a->azimuth, &a->elevation))
            return cli_fail(1, "render: --view takes A,E in degrees");
    } else if (!strcmp(o, "--size")) {
        if (parse_pair(v, 'x', &w, &h) || !(w >= 1 && w <= 16384 && h >= 1 && h <= 16384) ||
            w != floor(w) || h != floor(h))
            return cli_fail(1, "render: --size takes WxH, whole numbers in 1..16384");
        a->width = (uint32_t)w;
        a->height = (uint32_t)h;
    } else if (!strcmp(o, "--fov")) {
        if (cli_parse_double(v, &a->fov) || !(a->fov > 0 && a->fov < 170))
            return cli_fail(1, "render: --fov takes degrees in (0, 170)");
    } else if (!strcmp(o, "--stripes")) {
        if (cli_parse_double(v, &a->stripes) || !(a->stripes > 0 && a->stripes <= 1000))
            return cli_fail(1, "render: --stripes takes a number in (0, 1000]");
    } else if (!strcmp(o, "--range")) {
        if (parse_pair(v, ',', &a->range[0], &a->range[1]) || !(a->range[0] < a->range[1]))
            return cli_fail(1, "render: --range takes MIN,MAX with MIN < MAX");
        a->has_range = 1;
    } else if (!strcmp(o, "--colormap")) {
        if (!strcmp(v, "coolwarm"))
            a->colormap = FL_RENDER_COOLWARM;
        else if (!strcmp(v, "viridis"))
            a->colormap = FL_RENDER_VIRIDIS;
        else if (!strcmp(v, "gray"))
            a->colormap = FL_RENDER_GRAY;
        else
            return cli_fail(1, "render: --colormap is coolwarm, viridis or gray");
    } else if (!strcmp(o, "--background")) {
        if (parse_color(v, a->background))
            return cli_fail(1, "render: --background takes #rrggbb, #rrggbbaa or transparent");
    } else if (!strcmp(o, "--radius")) {
        if (cli_parse_double(v, &a->radius) || !(a->radius > 0))
            return cli_fail(1, "render: --radius takes a number > 0");
    } else if (!strcmp(o, "--field")) {
        a->field = v;
    } else {
        a->graph = v; /* --graph */
    }
    return 0;
}

static int parse(int argc, char **argv, cli_common *c, render_args *a)
{
    static const char *valued[] = {"--view",  "--size",     "--fov",        "--stripes",
                                   "--range", "--colormap", "--background", "--radius",
                                   "--field", "--graph"};
    struct {
        const char *name;
        int *flag;
    } flags[] = {{"--ortho", &a->ortho},         {"--aa", &a->aa},       {"--flat", &a->flat},
                 {"--wireframe", &a->wireframe}, {"--zebra", &a->zebra}, {"--closed", &a->closed},
                 {"--polygon", &a->polygon}};
    for (int i = 1; i < argc; i++) {
        int r = cli_common_option(c, argc, argv, &i);
        if (r < 0) return 1;
        if (r > 0) continue;
        const char *o = argv[i];
        int done = 0;
        for (size_t k = 0; !done && k < sizeof valued / sizeof *valued; k++)
            if (!strcmp(o, valued[k])) {
                if (i + 1 >= argc) return cli_fail(1, "render: %s needs a value", o);
                if (parse_value(a, o, argv[++i])) return 1;
                done = 1;
            }
        for (size_t k = 0; !done && k < sizeof flags / sizeof *flags; k++)
            if (!strcmp(o, flags[k].name)) *flags[k].flag = done = 1;
        if (done) continue;
        if (o[0] == '-' && o[1]) return cli_fail(1, "render: unknown option '%s' (see --help)", o);
        if (a->input) return cli_fail(1, "render: too many arguments ('%s')", o);
        a->input = o;
    }
    if (!c->help && !a->input) return cli_fail(1, "render: missing INPUT (see --help)");
    return 0;
}

/* The per-vertex values of --field: numbers separated by whitespace or commas, '#' comments. */
static fl_status read_field(const char *path, size_t expected, double **out, fl_error *err)
{
    *out = NULL;
    FILE *fp = fopen(path, "r");
    if (!fp) return fl_fail(err, FL_ERR_IO, path, -1, "cannot open: %s", strerror(errno));
    fl_vec v;
    fl_vec_init(&v, sizeof(double));
    char line[4096];
    long lineno = 0;
    fl_status st = FL_OK;
    while (st == FL_OK && fgets(line, sizeof line, fp)) {
        lineno++;
        char *hash = strchr(line, '#'), *p = line, *end;
        if (hash) *hash = '\0';
        for (;;) {
            while (*p == ' ' || *p == '\t' || *p == ',' || *p == '\r' || *p == '\n')
                p++;
            if (!*p) break;
            double x = strtod(p, &end);
            if (end == p || !isfinite(x)) {
                st = fl_fail(err, FL_ERR_INPUT, path, lineno, "expected a finite number");
                break;
            }
            if (fl_vec_push(&v, &x, 1)) st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
            p = end;
        }
    }
    fclose(fp);
    if (st == FL_OK && v.count != expected)
        st = fl_fail(err, FL_ERR_INPUT, path, -1, "has %zu values but the mesh has %zu vertices",
                     v.count, expected);
    if (st) {
        fl_vec_free(&v);
        return st;
    }
    *out = v.data;
    return FL_OK;
}

typedef struct render_result {
    const char *kind;
    uint32_t width, height;
    size_t covered, elements;
    int is_svg;
} render_result;

static fl_status add_mesh(const render_args *a, fl_render *r, const fl_mesh *m, fl_error *err)
{
    double *normals = NULL, *field = NULL;
    fl_status st = FL_OK;
    if (!a->flat) {
        normals = fl_alloc_array(m->vertex_count ? m->vertex_count : 1, 3 * sizeof(double));
        st = normals ? fl_render_vertex_normals(m, normals, err)
                     : fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    if (st == FL_OK && a->field) st = read_field(a->field, m->vertex_count, &field, err);
    if (st == FL_OK) {
        fl_render_mesh_style style = {0};
        style.normals = normals;
        style.scalars = field;
        style.colormap = a->colormap;
        if (a->has_range) {
            style.scalar_min = a->range[0];
            style.scalar_max = a->range[1];
        }
        style.wireframe = a->wireframe;
        style.zebra = a->zebra;
        style.zebra_stripes = a->stripes;
        st = fl_render_add_mesh(r, m, &style, err);
    }
    free(normals);
    free(field);
    return st;
}

static int is_ext(const char *path, const char *const *list)
{
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    for (; *list; list++)
        if (!strcmp(ext, *list)) return 1;
    return 0;
}

/* Loads INPUT into the scene: meshes, balls or 3D points. *done = 0 when INPUT is 2D. */
static fl_status load_3d(const render_args *a, fl_render *r, render_result *res, int *done,
                         fl_points *p2, fl_error *err)
{
    static const char *const mesh_ext[] = {"off", "obj", "ply", "stl", NULL};
    static const char *const ball_ext[] = {"xyzw", NULL};
    *done = 1;
    fl_status st;
    if (is_ext(a->input, mesh_ext)) {
        fl_mesh m;
        if ((st = fl_read_mesh(a->input, &m, err))) return st;
        if (m.triangle_count) {
            res->kind = "mesh";
            st = add_mesh(a, r, &m, err);
        } else {
            res->kind = "points";
            st = fl_render_add_points(r, m.xyz, m.vertex_count, a->radius, NULL, err);
        }
        fl_mesh_free(&m);
        return st;
    }
    if (is_ext(a->input, ball_ext)) {
        fl_balls b;
        if ((st = fl_read_balls(a->input, &b, err))) return st;
        res->kind = "balls";
        st = fl_render_add_balls(r, &b, NULL, err);
        fl_balls_free(&b);
        return st;
    }
    if ((st = fl_read_points(a->input, p2, err))) return st;
    if (p2->dim == 2) {
        *done = 0;
        return FL_OK;
    }
    res->kind = "points";
    st = fl_render_add_points(r, p2->coords, p2->count, a->radius, NULL, err);
    fl_points_free(p2);
    return st;
}

static fl_status svg_points(const render_args *a, fl_svg *svg, const fl_points *p, fl_error *err)
{
    fl_status st = FL_OK;
    if (a->graph) {
        fl_graph_kind kind;
        double param;
        fl_graph g = {0};
        st = fl_graph_kind_parse(a->graph, &kind, &param, err);
        if (st == FL_OK) st = fl_classic_graph(p->coords, p->count, 2, kind, param, &g, err);
        fl_svg_style edges = {.stroke = "#5b6770", .stroke_width = 1.5};
        if (st == FL_OK)
            st = fl_svg_add_edges(svg, p->coords, p->count, g.simplices, g.simplex_count, &edges,
                                  err);
        fl_graph_free(&g);
    }
    if (st == FL_OK && a->closed) st = fl_svg_add_polyline(svg, p->coords, p->count, 1, NULL, err);
    fl_svg_style dots = {.fill = "#b03a2e", .point_radius = 3};
    if (st == FL_OK) st = fl_svg_add_points(svg, p->coords, p->count, &dots, err);
    return st;
}

/* 2D inputs: polygons or points into an SVG canvas. `p` holds the points already read (or
 * nothing when INPUT is a polygon file). */
static fl_status render_svg(const render_args *a, const fl_points *p, const char *out,
                            render_result *res, fl_error *err)
{
    fl_svg *svg = NULL;
    double size = a->width ? (a->width > a->height ? a->width : a->height) : 0;
    fl_status st = fl_svg_new(size, &svg, err);
    if (st == FL_OK && p->count == 0) {
        fl_polygon poly;
        res->kind = "polygon";
        st = fl_read_polygon(a->input, &poly, err);
        if (st == FL_OK) st = fl_svg_add_polygon(svg, &poly, NULL, err);
        fl_polygon_free(&poly);
    } else if (st == FL_OK) {
        res->kind = "points";
        st = svg_points(a, svg, p, err);
    }
    if (st == FL_OK) st = fl_svg_write(svg, out, err);
    if (st == FL_OK) {
        double w, h;
        fl_svg_size(svg, &w, &h);
        res->width = (uint32_t)ceil(w);
        res->height = (uint32_t)ceil(h);
        res->elements = fl_svg_element_count(svg);
        res->is_svg = 1;
    }
    fl_svg_free(svg);
    return st;
}

static fl_status render_png(fl_render *r, const char *out, render_result *res, fl_error *err)
{
    fl_render_stats stats;
    fl_status st = cli_render_png(r, out, &stats, err);
    if (st == FL_OK) {
        res->width = stats.width;
        res->height = stats.height;
        res->covered = stats.pixels_covered;
    }
    return st;
}

/* INPUT's file name without directory and extension, with `ext` appended. */
static void default_output(const char *input, const char *ext, char *buf, size_t size)
{
    const char *base = strrchr(input, '/');
    base = base ? base + 1 : input;
    const char *dot = strrchr(base, '.');
    int n = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
    snprintf(buf, size, "%.*s.%s", n, base, ext);
}

static fl_status check_output(const char *out, int svg, fl_error *err)
{
    static const char *const png_ext[] = {"png", NULL}, *const svg_ext[] = {"svg", NULL};
    if (is_ext(out, svg ? svg_ext : png_ext)) return FL_OK;
    return fl_fail(err, FL_ERR_USAGE, out, -1, "this input renders to %s; name the output *.%s",
                   svg ? "SVG" : "PNG", svg ? "svg" : "png");
}

static fl_status run(const render_args *a, const cli_common *c, render_result *res, char *out,
                     size_t out_size, fl_error *err)
{
    static const char *const poly_ext[] = {"geojson", "json", NULL};
    fl_points p = {0};
    fl_status st = FL_OK;
    int three_d = 0;
    fl_render *r = NULL;
    if (!a->polygon && !is_ext(a->input, poly_ext)) {
        fl_render_options opt = {0};
        opt.width = a->width;
        opt.height = a->height;
        opt.azimuth = a->azimuth;
        opt.elevation = a->elevation;
        opt.orthographic = a->ortho;
        opt.fov = a->fov;
        opt.supersample = a->aa ? 2 : 1;
        opt.background = a->background;
        st = fl_render_new(&opt, &r, err);
        if (st == FL_OK) st = load_3d(a, r, res, &three_d, &p, err);
    }
    if (st == FL_OK) {
        if (c->output)
            snprintf(out, out_size, "%s", c->output);
        else
            default_output(a->input, three_d ? "png" : "svg", out, out_size);
        st = check_output(out, !three_d, err);
    }
    if (st == FL_OK) st = three_d ? render_png(r, out, res, err) : render_svg(a, &p, out, res, err);
    fl_render_free(r);
    fl_points_free(&p);
    return st;
}

int cmd_render(int argc, char **argv)
{
    cli_common c = {0};
    render_args a = {0};
    a.azimuth = 30;
    a.elevation = 20;
    memset(a.background, 255, 4);
    if (parse(argc, argv, &c, &a)) return 1;
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    double t0 = cli_now();
    fl_error err;
    render_result res = {0};
    char out[1024];
    fl_status st = run(&a, &c, &res, out, sizeof out, &err);
    if (st) return cli_report(&err);
    double seconds = cli_now() - t0;
    if (c.json) {
        cli_json j;
        cli_json_begin(&j, stdout);
        cli_json_string(&j, "kind", res.kind);
        cli_json_string(&j, "output", out);
        cli_json_uint(&j, "width", res.width);
        cli_json_uint(&j, "height", res.height);
        if (res.is_svg) {
            cli_json_null(&j, "pixels_covered");
            cli_json_uint(&j, "elements", res.elements);
        } else {
            cli_json_uint(&j, "pixels_covered", res.covered);
        }
        cli_json_double(&j, "seconds", seconds);
        cli_json_end(&j);
    } else if (!c.quiet) {
        if (res.is_svg)
            printf("wrote %s: %s, %ux%u, %zu shapes (%.3f s)\n", out, res.kind, res.width,
                   res.height, res.elements, seconds);
        else
            printf("wrote %s: %s, %ux%u, %zu pixels covered (%.3f s)\n", out, res.kind, res.width,
                   res.height, res.covered, seconds);
    }
    return 0;
}

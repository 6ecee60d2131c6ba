/* flintstone closest SHAPE QUERIES [-o OUT.csv] [--tolerance T] [--k N | --within D] [--closed]
 *                   [--hierarchy spatial|collapse]
 * Closest points on a triangle mesh or a polyline through the Meshsweeper hierarchy
 * (Guéziec §3-4): the spatial tree (fl_sweep_*) or the edge-collapse one (fl_sweep_collapse_*,
 * meshes only). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/commands.h"
#include "core/core.h"

static const char *usage_text =
    "usage: flintstone closest SHAPE QUERIES [-o OUT.csv] [--tolerance T] [--k N | --within D]\n"
    "                          [--closed] [--hierarchy spatial|collapse] [--json] [--quiet]\n"
    "\n"
    "For every query point, the closest point on SHAPE: a triangle mesh (.off .obj .ply .stl) or\n"
    "a polyline (a point file in order: .xy .xyz .csv .txt; --closed joins the last point to\n"
    "the first). Queries are a point file of the same dimension, answered in file order (a path\n"
    "of nearby queries is answered much faster).\n"
    "\n"
    "  --tolerance T  stop each query once its distance is known within T (an interval)\n"
    "  --k N          also list the N nearest elements of each query (CSV rows)\n"
    "  --within D     also list every element within distance D of each query (CSV rows)\n"
    "  --hierarchy H  spatial (default): a tree of triangles split top-down; collapse: the\n"
    "                 paper's edge-collapse hierarchy refined by vertex splits (meshes only;\n"
    "                 --k / --within run through one cursor, queries in file order)\n"
    "  -o OUT.csv     closest: query,distance,x,y,z,element,b0,b1,b2,lower,upper;\n"
    "                 with --k / --within: query,rank,element,distance\n"
    "  --json         queries, mean_distance, max_distance, seconds, queries_per_second\n"
    "\n"
    "example: flintstone closest mesh.off points.xyz -o closest.csv --json\n";

typedef struct closest_args {
    const char *shape, *queries;
    double tolerance, within;
    size_t k;
    int closed, has_within, collapse;
} closest_args;

static int parse(int argc, char **argv, cli_common *c, closest_args *a)
{
    for (int i = 1; i < argc; i++) {
        int r = cli_common_option(c, argc, argv, &i);
        if (r < 0) return 1;
        if (r > 0) continue;
        const char *o = argv[i];
        int value = !strcmp(o, "--tolerance") || !strcmp(o, "--k") || !strcmp(o, "--within") ||
                    !strcmp(o, "--hierarchy");
        if (value && i + 1 >= argc) return cli_fail(1, "closest: %s needs a value", o);
        if (!strcmp(o, "--tolerance")) {
            if (cli_parse_double(argv[++i], &a->tolerance) || a->tolerance < 0)
                return cli_fail(1, "closest: --tolerance takes a number >= 0");
        } else if (!strcmp(o, "--k")) {
            if (cli_parse_size(argv[++i], &a->k) || a->k == 0)
                return cli_fail(1, "closest: --k takes a whole number >= 1");
        } else if (!strcmp(o, "--within")) {
            if (cli_parse_double(argv[++i], &a->within) || a->within < 0)
                return cli_fail(1, "closest: --within takes a distance >= 0");
            a->has_within = 1;
        } else if (!strcmp(o, "--hierarchy")) {
            const char *h = argv[++i];
            if (strcmp(h, "spatial") && strcmp(h, "collapse"))
                return cli_fail(1, "closest: --hierarchy takes spatial or collapse");
            a->collapse = !strcmp(h, "collapse");
        } else if (!strcmp(o, "--closed")) {
            a->closed = 1;
        } else if (o[0] == '-' && o[1]) {
            return cli_fail(1, "closest: unknown option '%s' (see --help)", o);
        } else if (!a->shape) {
            a->shape = o;
        } else if (!a->queries) {
            a->queries = o;
        } else {
            return cli_fail(1, "closest: too many arguments ('%s')", o);
        }
    }
    if (a->k && a->has_within) return cli_fail(1, "closest: give --k or --within, not both");
    return 0;
}

static int is_mesh_file(const char *path)
{
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    return !strcmp(ext, "off") || !strcmp(ext, "obj") || !strcmp(ext, "ply") || !strcmp(ext, "stl");
}

/* The shape's hierarchy: *s (spatial) or, with --hierarchy collapse, *hc. */
static fl_status build_shape(const closest_args *a, fl_sweep **s, fl_sweep_collapse **hc,
                             fl_error *err)
{
    if (is_mesh_file(a->shape)) {
        fl_mesh m;
        fl_status st = fl_read_mesh(a->shape, &m, err);
        if (st) return st;
        st = a->collapse ? fl_sweep_collapse_build(&m, NULL, hc, err)
                         : fl_sweep_build(&m, NULL, s, err);
        fl_mesh_free(&m);
        return st;
    }
    if (a->collapse)
        return fl_fail(err, FL_ERR_INPUT, a->shape, -1,
                       "--hierarchy collapse needs a triangle mesh (.off .obj .ply .stl)");
    fl_points p;
    fl_status st = fl_read_points(a->shape, &p, err);
    if (st) return st;
    st = fl_sweep_polyline_build(p.coords, p.count, p.dim, a->closed, NULL, s, err);
    fl_points_free(&p);
    return st;
}

static void write_closest_row(FILE *fp, size_t i, const fl_closest *r)
{
    fprintf(fp, "%zu,%.17g,%.17g,%.17g,%.17g,%ld,%.17g,%.17g,%.17g,%.17g,%.17g\n", i, r->distance,
            r->point[0], r->point[1], r->point[2],
            r->element == FL_SWEEP_NONE ? -1L : (long)r->element, r->bary[0], r->bary[1],
            r->bary[2], r->lower, r->upper);
}

/* One --k / --within query on whichever hierarchy was built (c: a cursor on the collapse
 * hierarchy, kept across the queries for §5.1). */
static fl_status neighbours_one(const closest_args *a, const fl_sweep *s,
                                fl_sweep_collapse_cursor *c, const double *qi, uint32_t *el,
                                double *d, size_t *found, fl_sweep_hits *hits, fl_error *err)
{
    if (a->k)
        return c ? fl_sweep_collapse_cursor_knearest(c, qi, a->k, el, d, found, err)
                 : fl_sweep_knearest(s, qi, a->k, el, d, found, err);
    return c ? fl_sweep_collapse_cursor_within(c, qi, a->within, hits, err)
             : fl_sweep_within(s, qi, a->within, hits, err);
}

/* --k / --within: the ranked element lists, one CSV row an element. */
static fl_status write_neighbours(const closest_args *a, const fl_sweep *s,
                                  const fl_sweep_collapse *hc, const fl_points *q, FILE *fp,
                                  fl_error *err)
{
    fputs("query,rank,element,distance\n", fp);
    size_t k = a->k;
    uint32_t *el = k ? fl_alloc_array(k, sizeof *el) : NULL;
    double *d = k ? fl_alloc_array(k, sizeof *d) : NULL;
    if (k && (!el || !d)) {
        free(el);
        free(d);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    fl_sweep_collapse_cursor *c = NULL;
    fl_status st = hc ? fl_sweep_collapse_cursor_new(hc, &c, err) : FL_OK;
    for (size_t i = 0; st == FL_OK && i < q->count; i++) {
        size_t found = 0;
        fl_sweep_hits hits = {0};
        st = neighbours_one(a, s, c, q->coords + (size_t)q->dim * i, el, d, &found, &hits, err);
        for (size_t j = 0; st == FL_OK && j < found; j++)
            fprintf(fp, "%zu,%zu,%u,%.17g\n", i, j, el[j], d[j]);
        for (size_t j = 0; st == FL_OK && j < hits.count; j++)
            fprintf(fp, "%zu,%zu,%u,%.17g\n", i, j, hits.element[j], hits.distance[j]);
        fl_sweep_hits_free(&hits);
    }
    fl_sweep_collapse_cursor_free(c);
    free(el);
    free(d);
    return st;
}

static fl_status run(const cli_common *c, const closest_args *a, const fl_sweep *s,
                     const fl_sweep_collapse *hc, const fl_points *q, fl_closest *res,
                     fl_error *err)
{
    fl_status st = hc ? fl_sweep_collapse_closest(hc, q->coords, q->count, a->tolerance, res, err)
                      : fl_sweep_closest(s, q->coords, q->count, a->tolerance, res, err);
    if (st || !c->output) return st;
    fl_out_file out;
    if ((st = fl_out_open(&out, c->output, 0, err))) return st;
    if (a->k || a->has_within) {
        st = write_neighbours(a, s, hc, q, out.fp, err);
    } else {
        fputs("query,distance,x,y,z,element,b0,b1,b2,lower,upper\n", out.fp);
        for (size_t i = 0; i < q->count; i++)
            write_closest_row(out.fp, i, &res[i]);
    }
    if (st) {
        fl_out_abort(&out);
        return st;
    }
    return fl_out_commit(&out, err);
}

int cmd_closest(int argc, char **argv)
{
    cli_common c = {0};
    closest_args a = {0};
    if (parse(argc, argv, &c, &a)) return 1;
    if (c.help) {
        fputs(usage_text, stdout);
        return 0;
    }
    if (!a.queries) return cli_fail(1, "closest: needs SHAPE and QUERIES (see --help)");
    fl_error err;
    fl_sweep *s = NULL;
    fl_sweep_collapse *hc = NULL;
    fl_points q = {0};
    double t0 = cli_now();
    fl_status st = build_shape(&a, &s, &hc, &err);
    int dim = hc ? 3 : fl_sweep_dim(s);
    size_t elements = 0;
    fl_sweep_collapse_info info = {0};
    if (st == FL_OK && hc) fl_sweep_collapse_info_get(hc, &info, NULL);
    elements = hc ? info.fine_triangles : fl_sweep_element_count(s);
    if (st == FL_OK) st = fl_read_points(a.queries, &q, &err);
    if (st == FL_OK && q.dim != dim)
        st = fl_fail(&err, FL_ERR_INPUT, a.queries, -1, "queries are %dD but the shape is %dD",
                     q.dim, dim);
    fl_closest *res = st == FL_OK ? fl_alloc_array(q.count, sizeof *res) : NULL;
    if (st == FL_OK && !res) st = fl_fail(&err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    double t1 = cli_now();
    if (st == FL_OK) st = run(&c, &a, s, hc, &q, res, &err);
    double query_seconds = cli_now() - t1;
    if (st == FL_OK) {
        double sum = 0, max = 0;
        for (size_t i = 0; i < q.count; i++) {
            sum += res[i].distance;
            max = fmax(max, res[i].distance);
        }
        double mean = q.count ? sum / (double)q.count : 0;
        if (c.json) {
            cli_json j;
            cli_json_begin(&j, stdout);
            cli_json_uint(&j, "queries", q.count);
            cli_json_uint(&j, "elements", elements);
            cli_json_double(&j, "mean_distance", mean);
            cli_json_double(&j, "max_distance", max);
            cli_json_double(&j, "seconds", cli_now() - t0);
            cli_json_double(&j, "queries_per_second",
                            query_seconds > 0 ? (double)q.count / query_seconds : 0);
            cli_json_end(&j);
        } else if (!c.quiet) {
            printf("%zu queries on %zu elements: mean distance %.6g, max %.6g (%.3f s)\n", q.count,
                   elements, mean, max, cli_now() - t0);
        }
    }
    free(res);
    fl_points_free(&q);
    fl_sweep_free(s);
    fl_sweep_collapse_free(hc);
    return st ? cli_report(&err) : 0;
}

/* GeoJSON polygons (RFC 7946). Reading keeps Polygon and MultiPolygon geometries wherever they
 * appear: at the top level, as a Feature's geometry, in a FeatureCollection's features or a
 * GeometryCollection's geometries. Other geometry types (Point, LineString, ...) are skipped;
 * a file without any polygon is an error. Positions may carry a z (or more); only x and y are
 * kept. Rings must be closed as §3.1.6 requires (last position = first); the repeat is
 * dropped because fl_polygon rings are closed implicitly. Ring orientation is kept as given:
 * §3.1.6 asks parsers not to reject rings against the right-hand rule. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "io/io_internal.h"
#include "io/json.h"
#include "io/text_scan.h"

typedef struct builder {
    const char *name;
    const fl_json_doc *doc;
    fl_vec xy;            /* doubles, two a vertex */
    fl_vec ring_start;    /* size_t */
    fl_vec polygon_start; /* size_t */
    fl_error *err;
} builder;

static fl_status fail_node(builder *b, size_t node, const char *fmt, ...) FL_PRINTF(3, 4);

static fl_status fail_node(builder *b, size_t node, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return fl_fail(b->err, FL_ERR_INPUT, b->name, b->doc->nodes[node].line, "%s", msg);
}

static fl_status out_of_memory(builder *b)
{
    return fl_fail(b->err, FL_ERR_NOMEM, b->name, -1, "out of memory reading GeoJSON");
}

static const fl_json_node *node(const builder *b, size_t i)
{
    return &b->doc->nodes[i];
}

/* A position: [x, y] or [x, y, z, ...], numbers only (§3.1.1). */
static fl_status read_position(builder *b, size_t pos, double xy[2])
{
    const fl_json_node *p = node(b, pos);
    if (p->type != FL_JSON_ARRAY || p->u.children.count < 2)
        return fail_node(b, pos, "a position must be an array of 2 or 3 numbers, got %s",
                         p->type == FL_JSON_ARRAY ? "fewer than 2" : "something else");
    size_t i = 0;
    for (size_t c = p->u.children.first; c != FL_JSON_NONE; c = node(b, c)->next, i++) {
        if (node(b, c)->type != FL_JSON_NUMBER)
            return fail_node(b, c, "a coordinate must be a number");
        if (!isfinite(node(b, c)->u.number))
            return fail_node(b, c, "coordinate is beyond the range of a double");
        if (i < 2) xy[i] = node(b, c)->u.number;
    }
    return FL_OK;
}

static fl_status read_ring(builder *b, size_t ring)
{
    const fl_json_node *r = node(b, ring);
    if (r->type != FL_JSON_ARRAY) return fail_node(b, ring, "a ring must be an array of positions");
    size_t start = b->xy.count / 2;
    for (size_t c = r->u.children.first; c != FL_JSON_NONE; c = node(b, c)->next) {
        double xy[2];
        fl_status st = read_position(b, c, xy);
        if (st != FL_OK) return st;
        if (fl_vec_push(&b->xy, xy, 2)) return out_of_memory(b);
    }
    size_t n = b->xy.count / 2 - start;
    const double *v = (const double *)b->xy.data + 2 * start;
    if (n < 2 || v[0] != v[2 * n - 2] || v[1] != v[2 * n - 1])
        return fail_node(b, ring,
                         "ring is not closed: its last position must repeat the first "
                         "(RFC 7946 section 3.1.6)");
    b->xy.count -= 2;
    if (n - 1 < 3)
        return fail_node(b, ring, "ring has %zu distinct positions; a ring needs at least 3",
                         n - 1);
    return fl_vec_push(&b->ring_start, &start, 1) ? out_of_memory(b) : FL_OK;
}

/* Polygon coordinates: the outer ring, then the holes (§3.1.6). An empty array is an empty
 * polygon and adds nothing. */
static fl_status read_polygon(builder *b, size_t coords)
{
    const fl_json_node *c = node(b, coords);
    if (c->type != FL_JSON_ARRAY)
        return fail_node(b, coords, "polygon coordinates must be an array of rings");
    if (c->u.children.count == 0) return FL_OK;
    size_t first_ring = b->ring_start.count;
    if (fl_vec_push(&b->polygon_start, &first_ring, 1)) return out_of_memory(b);
    for (size_t r = c->u.children.first; r != FL_JSON_NONE; r = node(b, r)->next) {
        fl_status st = read_ring(b, r);
        if (st != FL_OK) return st;
    }
    return FL_OK;
}

/* The array member `key` of object `obj` (each element goes to read_object or
 * read_polygon). */
static fl_status array_member(builder *b, size_t obj, const char *key, size_t *array)
{
    *array = fl_json_member(b->doc, obj, key);
    if (*array == FL_JSON_NONE || node(b, *array)->type != FL_JSON_ARRAY)
        return fail_node(b, obj, "this object needs an array member \"%s\"", key);
    return FL_OK;
}

static fl_status read_object(builder *b, size_t obj);

static fl_status read_each(builder *b, size_t array, int polygons)
{
    for (size_t c = node(b, array)->u.children.first; c != FL_JSON_NONE; c = node(b, c)->next) {
        fl_status st = polygons ? read_polygon(b, c) : read_object(b, c);
        if (st != FL_OK) return st;
    }
    return FL_OK;
}

static int is_skipped_geometry(const builder *b, size_t type)
{
    static const char *const skipped[] = {"Point", "MultiPoint", "LineString", "MultiLineString"};
    for (size_t i = 0; i < sizeof skipped / sizeof skipped[0]; i++)
        if (fl_json_is_string(b->doc, type, skipped[i])) return 1;
    return 0;
}

static fl_status read_object(builder *b, size_t obj)
{
    if (node(b, obj)->type != FL_JSON_OBJECT)
        return fail_node(b, obj, "expected a GeoJSON object ({\"type\": ...})");
    size_t type = fl_json_member(b->doc, obj, "type");
    if (type == FL_JSON_NONE || node(b, type)->type != FL_JSON_STRING)
        return fail_node(b, obj, "GeoJSON object without a \"type\" string");
    size_t member;
    fl_status st = FL_OK;
    if (fl_json_is_string(b->doc, type, "FeatureCollection")) {
        if ((st = array_member(b, obj, "features", &member)) == FL_OK) st = read_each(b, member, 0);
    } else if (fl_json_is_string(b->doc, type, "Feature")) {
        member = fl_json_member(b->doc, obj, "geometry");
        if (member != FL_JSON_NONE && node(b, member)->type != FL_JSON_NULL)
            st = read_object(b, member);
    } else if (fl_json_is_string(b->doc, type, "GeometryCollection")) {
        if ((st = array_member(b, obj, "geometries", &member)) == FL_OK)
            st = read_each(b, member, 0);
    } else if (fl_json_is_string(b->doc, type, "Polygon")) {
        if ((st = array_member(b, obj, "coordinates", &member)) == FL_OK)
            st = read_polygon(b, member);
    } else if (fl_json_is_string(b->doc, type, "MultiPolygon")) {
        if ((st = array_member(b, obj, "coordinates", &member)) == FL_OK)
            st = read_each(b, member, 1);
    } else if (!is_skipped_geometry(b, type)) {
        char q[40];
        const fl_json_node *t = node(b, type);
        fl_scan_quote(b->doc->strings + t->u.string.off, t->u.string.len, q, sizeof q);
        st = fail_node(b, type, "unknown GeoJSON type \"%s\"", q);
    }
    return st;
}

static fl_status finish(builder *b, fl_polygon *out)
{
    size_t vertices = b->xy.count / 2, rings = b->ring_start.count;
    if (rings == 0)
        return fl_fail(b->err, FL_ERR_INPUT, b->name, -1, "no Polygon or MultiPolygon in file");
    if (fl_vec_push(&b->ring_start, &vertices, 1) || fl_vec_push(&b->polygon_start, &rings, 1))
        return out_of_memory(b);
    out->vertex_count = vertices;
    out->ring_count = rings;
    out->polygon_count = b->polygon_start.count - 1;
    out->xy = fl_vec_release(&b->xy);
    out->ring_start = fl_vec_release(&b->ring_start);
    out->polygon_start = fl_vec_release(&b->polygon_start);
    return FL_OK;
}

fl_status fl_geojson_parse(const char *name, const char *data, size_t size, fl_polygon *out,
                           fl_error *err)
{
    memset(out, 0, sizeof *out);
    fl_json_doc doc;
    fl_status st = fl_json_parse(name, data, size, &doc, err);
    if (st != FL_OK) return st;
    builder b = {.name = name, .doc = &doc, .err = err};
    fl_vec_init(&b.xy, sizeof(double));
    fl_vec_init(&b.ring_start, sizeof(size_t));
    fl_vec_init(&b.polygon_start, sizeof(size_t));
    st = read_object(&b, 0);
    if (st == FL_OK) st = finish(&b, out);
    fl_vec_free(&b.xy);
    fl_vec_free(&b.ring_start);
    fl_vec_free(&b.polygon_start);
    fl_json_free(&doc);
    return st;
}

static void write_position(FILE *fp, const double *v)
{
    fprintf(fp, "[%.17g, %.17g]", v[0], v[1]);
}

/* One ring as a closed GeoJSON ring: the first position is repeated at the end (§3.1.6). */
static void write_ring(FILE *fp, const fl_polygon *polygon, size_t r)
{
    size_t first = polygon->ring_start[r], end = polygon->ring_start[r + 1];
    fputc('[', fp);
    for (size_t i = first; i < end; i++) {
        write_position(fp, &polygon->xy[2 * i]);
        fputs(", ", fp);
    }
    write_position(fp, &polygon->xy[2 * first]);
    fputc(']', fp);
}

/* A FeatureCollection with one Feature whose geometry is a MultiPolygon: the form every GIS
 * tool opens. Rings are written in the order and orientation given. */
fl_status fl_geojson_write(FILE *fp, const fl_polygon *polygon)
{
    fputs("{\"type\": \"FeatureCollection\", \"features\": [{\"type\": \"Feature\", "
          "\"properties\": {},\n\"geometry\": {\"type\": \"MultiPolygon\", \"coordinates\": [",
          fp);
    for (size_t p = 0; p < polygon->polygon_count; p++) {
        fputs(p > 0 ? ",\n[" : "\n[", fp);
        for (size_t r = polygon->polygon_start[p]; r < polygon->polygon_start[p + 1]; r++) {
            if (r > polygon->polygon_start[p]) fputs(",\n ", fp);
            write_ring(fp, polygon, r);
        }
        fputc(']', fp);
    }
    fputs("\n]}}]}\n", fp);
    return ferror(fp) ? FL_ERR_IO : FL_OK;
}

/* GeoJSON polygons and the JSON reader beneath: RFC 7946 structures, holes, collections,
 * escapes, and malformed input reported with the right line, without deep recursion. */
#include "io/io_internal.h"
#include "io/json.h"
#include "io_test_util.h"

static fl_status parse(const char *text, fl_polygon *poly, fl_error *err)
{
    return fl_geojson_parse("t.geojson", text, strlen(text), poly, err);
}

static void test_geojson_polygon_with_hole(void)
{
    const char *text = "{\"type\": \"Polygon\",\n"
                       " \"coordinates\": [\n"
                       "  [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]],\n"
                       "  [[2, 2], [2, 4], [4, 4.5], [2, 2]]\n"
                       " ]}\n";
    fl_polygon p;
    fl_error err;
    CHECK_STATUS(parse(text, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.polygon_count, 1);
    CHECK_EQ_INT(p.ring_count, 2);
    CHECK_EQ_INT(p.vertex_count, 7);
    if (p.ring_count == 2 && p.vertex_count == 7) {
        CHECK_EQ_INT(p.ring_start[1], 4);
        CHECK_EQ_INT(p.ring_start[2], 7);
        CHECK_EQ_INT(p.polygon_start[1], 2);
        CHECK(p.xy[4] == 10 && p.xy[5] == 10 && p.xy[12] == 4 && p.xy[13] == 4.5);
    }
    fl_polygon_free(&p);
}

static void test_geojson_multipolygon_and_3d_positions(void)
{
    /* Member order is free in JSON: "coordinates" may come before "type". */
    const char *text = "{\"coordinates\": [\n"
                       " [[[0,0,5],[1,0,5],[0,1,5],[0,0,5]]],\n"
                       " [[[5,5],[9,5],[9,9],[5,9],[5,5]], [[6,6],[7,6],[7,7],[6,6]]]\n"
                       "], \"type\": \"MultiPolygon\"}";
    fl_polygon p;
    fl_error err;
    CHECK_STATUS(parse(text, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.polygon_count, 2);
    CHECK_EQ_INT(p.ring_count, 3);
    CHECK_EQ_INT(p.vertex_count, 10);
    if (p.polygon_count == 2 && p.ring_count == 3) {
        CHECK_EQ_INT(p.polygon_start[1], 1);
        CHECK_EQ_INT(p.polygon_start[2], 3);
        CHECK(p.xy[2] == 1 && p.xy[3] == 0);
    }
    fl_polygon_free(&p);
}

static void test_geojson_feature_collection_skips_other_geometries(void)
{
    const char *text =
        "{\"type\": \"FeatureCollection\", \"features\": [\n"
        " {\"type\": \"Feature\", \"properties\": {\"name\": \"p\\\"q\\\\r\\/s\\u00e9\\n\","
        " \"nested\": {\"a\": [1, {\"b\": [true, false, null]}], \"\\u0074ype\": \"x\"}},\n"
        "  \"geometry\": {\"type\": \"Point\", \"coordinates\": [1, 2]}},\n"
        " {\"type\": \"Feature\", \"properties\": null, \"geometry\": null},\n"
        " {\"type\": \"Feature\", \"properties\": {},\n"
        "  \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,0],[1,1],[0,0]]]}},\n"
        " {\"type\": \"Feature\", \"geometry\": {\"type\": \"GeometryCollection\", \"geometries\": "
        "[\n"
        "   {\"type\": \"LineString\", \"coordinates\": [[0,0],[1,1]]},\n"
        "   {\"type\": \"MultiPolygon\", \"coordinates\": [[[[3,3],[4,3],[4,4],[3,3]]]]}]}}\n"
        "]}\n";
    fl_polygon p;
    fl_error err;
    CHECK_STATUS(parse(text, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.polygon_count, 2);
    CHECK_EQ_INT(p.ring_count, 2);
    CHECK_EQ_INT(p.vertex_count, 6);
    if (p.vertex_count == 6) CHECK(p.xy[6] == 3 && p.xy[11] == 4);
    fl_polygon_free(&p);
}

/* The decoded bytes are compared with the UTF-8 encodings of U+00E9 and U+1F600 (a surrogate
 * pair in JSON), as given by the Unicode standard. */
static void test_json_string_escapes_decode_to_utf8(void)
{
    const char *text =
        "{\"k\\u0065y\": \"a\\\"b\\\\c\\/d\\b\\f\\n\\r\\t\\u00e9\\ud83d\\ude00\\ud800x\"}";
    fl_json_doc doc;
    fl_error err;
    CHECK_STATUS(fl_json_parse("t.json", text, strlen(text), &doc, &err), FL_OK, &err);
    size_t v = fl_json_member(&doc, 0, "key");
    CHECK(v != FL_JSON_NONE);
    if (v != FL_JSON_NONE) {
        const char want[] = "a\"b\\c/d\b\f\n\r\t\xC3\xA9\xF0\x9F\x98\x80\xEF\xBF\xBDx";
        CHECK_EQ_INT(doc.nodes[v].u.string.len, sizeof want - 1);
        CHECK(memcmp(doc.strings + doc.nodes[v].u.string.off, want, sizeof want - 1) == 0);
    }
    fl_json_free(&doc);
}

static void test_json_numbers_follow_the_grammar(void)
{
    const char *text = "[-0, 0.5, 1e2, 1E-2, -12.5e+1, 123456789012345678901234567890]";
    const double want[] = {-0.0, 0.5, 1e2, 1E-2, -12.5e+1, 123456789012345678901234567890.0};
    fl_json_doc doc;
    fl_error err;
    CHECK_STATUS(fl_json_parse("t.json", text, strlen(text), &doc, &err), FL_OK, &err);
    size_t i = 0;
    for (size_t c = doc.nodes[0].u.children.first; c != FL_JSON_NONE; c = doc.nodes[c].next, i++)
        CHECK(i < 6 && doc.nodes[c].u.number == want[i]);
    CHECK_EQ_INT(i, 6);
    fl_json_free(&doc);
    static const char *bad[] = {"-", "01", "1.", ".5", "1e", "+1", "0x10", "NaN", "1e1x"};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char t[64];
        snprintf(t, sizeof t, "[\n%s]", bad[k]);
        fl_status st = fl_json_parse("t.json", t, strlen(t), &doc, &err);
        CHECK_MSG(st == FL_ERR_INPUT && err.line == 2, "'%s' gave %d at line %ld", bad[k], (int)st,
                  err.line);
        if (st == FL_OK) fl_json_free(&doc);
    }
}

/* Each malformed input must fail with FL_ERR_INPUT at the line where the problem is. */
static void test_geojson_malformed_inputs_name_their_line(void)
{
    static const struct {
        const char *text;
        long line;
        const char *needle;
    } cases[] = {
        {"{\"type\": \"Polygon\",\n \"coordinates\": [[[0,0],[1,0],[1,1],[0,0]]],\n"
         " \"properties\": {\"name\": \"abc}}",
         3, "unterminated string"},
        {"{\"type\": \"Polygon\",\n \"coordinates\": [[[0,0],[1,0],[1,1],[0,0],]]}\n", 2,
         "trailing comma before ']'"},
        {"{\"type\": \"Polygon\",\n\"coordinates\": [],\n}", 3, "trailing comma before '}'"},
        {"{\"type\": \"Polygon\", \"coordinates\": [\n[[0,0],[1,0],\n[1],[0,0]]]}", 3,
         "position must be an array of 2 or 3 numbers"},
        {"{\"type\": \"Polygon\", \"coordinates\": [\n[[0,0],[1,0],[1,1],[0,0]],\n"
         "[[2,2],[3,2],[3,3],[2,2.5]]]}",
         3, "not closed"},
        {"{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,0],\n[\"1\",1],[0,0]]]}", 2,
         "coordinate must be a number"},
        {"{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,0],\n[NaN,1],[0,0]]]}", 2,
         "expected a value"},
        {"{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,0],[0,0]]]}", 1,
         "2 distinct positions"},
        {"{\"type\": \"Point\", \"coordinates\": [0, 0]}", -1, "no Polygon or MultiPolygon"},
        {"{\"type\": \"Polygon\", \"properties\": {\"big\": 1e999},\n"
         "\"coordinates\": [[[0,0],[1,0],\n[-1e400,1],[0,0]]]}",
         3, "beyond the range of a double"},
        {"{\"type\": \"Circle\",\n\"radius\": 1}", 1, "unknown GeoJSON type \"Circle\""},
        {"\n{\"type\": \"Polygon\"}", 2, "needs an array member \"coordinates\""},
        {"{\"coordinates\": []}", 1, "without a \"type\""},
        {"[1, 2]", 1, "expected a GeoJSON object"},
        {"{\"type\": \"Polygon\", \"coordinates\": []}\n{}", 2, "extra data"},
        {"{\"type\": \"Poly\ngon\"}", 1, "control character"},
        {"{\"type\":\n \"\\x\"}", 2, "invalid escape"},
        {"{\"type\" \"Polygon\"}", 1, "expected ':'"},
        {"{type: 1}", 1, "member name in double quotes"},
        {"[1 2]", 1, "expected ',' or ']'"},
        {"\n\n", 3, "unexpected end of file"},
        {"{\"a\": [1,\n2", 2, "inside the array that starts at line 1"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fl_polygon p;
        fl_error err;
        fl_status st = parse(cases[i].text, &p, &err);
        CHECK_MSG(st == FL_ERR_INPUT && err.line == cases[i].line &&
                      strstr(err.message, cases[i].needle) != NULL,
                  "case %zu: status %d line %ld message '%s'", i, (int)st, err.line, err.message);
        CHECK(p.xy == NULL && p.ring_count == 0);
    }
}

/* 10000 nested brackets must be refused at the depth limit, not recurse 10000 times. */
static void test_json_depth_bomb_is_refused(void)
{
    size_t n = 10000;
    char *text = malloc(n + 1);
    memset(text, '[', n);
    text[n] = '\0';
    fl_polygon p;
    fl_error err;
    fl_status st = fl_geojson_parse("bomb.geojson", text, n, &p, &err);
    CHECK_INPUT_ERROR(st, err, 1, "nested deeper than 64");
    memset(text, '{', n);
    st = fl_geojson_parse("bomb.geojson", text, n, &p, &err);
    CHECK_EQ_INT(st, FL_ERR_INPUT);
    free(text);
    /* Exactly the limit is fine. */
    char ok[2 * FL_JSON_MAX_DEPTH + 1];
    memset(ok, '[', FL_JSON_MAX_DEPTH);
    memset(ok + FL_JSON_MAX_DEPTH, ']', FL_JSON_MAX_DEPTH);
    fl_json_doc doc;
    CHECK_STATUS(fl_json_parse("deep.json", ok, 2 * FL_JSON_MAX_DEPTH, &doc, &err), FL_OK, &err);
    fl_json_free(&doc);
}

static void test_geojson_unterminated_buffer_not_overread(void)
{
    static const char *texts[] = {
        "{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,0],[1,1],[0,0]]]}",
        "{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,0],[1,1],[0,0]]]} 12",
        "[1.5e",
        "\"abc\\u12",
        "tru",
        "[-",
        "{\"a\"",
        "\"\\"};
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        size_t n;
        char *buf = io_test_unterminated(texts[i], &n);
        fl_polygon p;
        fl_error err;
        fl_status st = fl_geojson_parse("t.geojson", buf, n, &p, &err);
        CHECK_EQ_INT(st, i == 0 ? FL_OK : FL_ERR_INPUT);
        fl_polygon_free(&p);
        free(buf);
    }
}

/* Write then read gives back the same doubles, rings and polygons (holes stay holes). */
static void test_geojson_round_trip_is_exact(void)
{
    unsigned long long rng = 11;
    enum { V = 14 };
    double xy[2 * V];
    for (int i = 0; i < 2 * V; i++)
        xy[i] = (fl_test_rand01(&rng) - 0.5) * 3e5 / 7.0;
    xy[0] = -0.0;
    xy[1] = 1e-310;
    size_t ring_start[] = {0, 4, 7, 10, 14};
    size_t polygon_start[] = {0, 3, 4};
    fl_polygon in = {V, xy, 4, ring_start, 2, polygon_start};
    char *text;
    size_t size;
    fl_status st = FL_ERR_IO;
    IO_TEST_CAPTURE(fl_geojson_write(fp, &in), text, size, st);
    CHECK_EQ_INT(st, FL_OK);
    fl_polygon out;
    fl_error err;
    CHECK_STATUS(fl_geojson_parse("rt.geojson", text, size, &out, &err), FL_OK, &err);
    CHECK_EQ_INT(out.vertex_count, V);
    CHECK_EQ_INT(out.ring_count, 4);
    CHECK_EQ_INT(out.polygon_count, 2);
    if (out.vertex_count == V && out.ring_count == 4 && out.polygon_count == 2) {
        CHECK(memcmp(out.xy, xy, sizeof xy) == 0);
        CHECK(memcmp(out.ring_start, ring_start, sizeof ring_start) == 0);
        CHECK(memcmp(out.polygon_start, polygon_start, sizeof polygon_start) == 0);
    }
    fl_polygon_free(&out);
    free(text);
}

/* Random byte edits of a valid file must never crash or read out of bounds (ASan watches), and
 * each result is either a consistent polygon or FL_ERR_INPUT with a zeroed output. */
static void test_geojson_mutated_inputs_fail_cleanly(void)
{
    const char *seed = "{\"type\": \"FeatureCollection\", \"features\": [\n"
                       " {\"type\": \"Feature\", \"properties\": {\"n\": \"a\\u00e9\\n\"},\n"
                       "  \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [\n"
                       "   [[0,0],[4,0],[4,4],[0,4],[0,0]], [[1,1],[1,2],[2,2],[1,1]]]}},\n"
                       " {\"type\": \"Feature\", \"geometry\": {\"type\": \"MultiPolygon\",\n"
                       "  \"coordinates\": [[[[5,5],[6,5],[6,6e0],[5,5]]]]}}]}\n";
    static const char alphabet[] = "{}[],:\"\\-+.eE0123456789 \nabnutrfl\x01\xff";
    size_t n = strlen(seed);
    unsigned long long rng = 99;
    int ok = 0;
    for (int trial = 0; trial < 3000; trial++) {
        char *buf = malloc(n);
        memcpy(buf, seed, n);
        size_t len = n;
        int edits = 1 + (int)(fl_test_rand_u64(&rng) % 3);
        for (int e = 0; e < edits; e++) {
            size_t at = (size_t)(fl_test_rand_u64(&rng) % len);
            unsigned long long kind = fl_test_rand_u64(&rng) % 3;
            if (kind == 0)
                buf[at] = alphabet[fl_test_rand_u64(&rng) % (sizeof alphabet - 1)];
            else if (kind == 1)
                len = at + 1; /* truncate */
            else
                memmove(buf + at, buf + at + 1, --len - at); /* delete a byte */
            if (len == 0) break;
        }
        fl_polygon p;
        fl_error err;
        fl_status st = fl_geojson_parse("m.geojson", buf, len, &p, &err);
        if (st == FL_OK) {
            ok++;
            CHECK(p.ring_start[0] == 0 && p.ring_start[p.ring_count] == p.vertex_count);
            CHECK(p.polygon_start[p.polygon_count] == p.ring_count);
            for (size_t r = 0; r < p.ring_count; r++)
                CHECK(p.ring_start[r + 1] - p.ring_start[r] >= 3);
        } else {
            CHECK_EQ_INT(st, FL_ERR_INPUT);
            CHECK(p.xy == NULL && p.ring_start == NULL && p.polygon_start == NULL);
            long lines = 1;
            for (size_t i = 0; i < len; i++)
                lines += buf[i] == '\n';
            CHECK(err.line >= -1 && err.line <= lines && err.line != 0);
        }
        fl_polygon_free(&p);
        free(buf);
    }
    CHECK(ok > 0); /* some edits (e.g. a digit for a digit) keep the file valid */
}

FL_TEST_MAIN(FL_TEST_CASE(test_geojson_polygon_with_hole),
             FL_TEST_CASE(test_geojson_multipolygon_and_3d_positions),
             FL_TEST_CASE(test_geojson_feature_collection_skips_other_geometries),
             FL_TEST_CASE(test_json_string_escapes_decode_to_utf8),
             FL_TEST_CASE(test_json_numbers_follow_the_grammar),
             FL_TEST_CASE(test_geojson_malformed_inputs_name_their_line),
             FL_TEST_CASE(test_json_depth_bomb_is_refused),
             FL_TEST_CASE(test_geojson_unterminated_buffer_not_overread),
             FL_TEST_CASE(test_geojson_round_trip_is_exact),
             FL_TEST_CASE(test_geojson_mutated_inputs_fail_cleanly))

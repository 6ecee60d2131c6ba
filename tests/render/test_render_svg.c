/* The SVG canvas: well-formed output (a minimal XML tag-balance check), the element counts the
 * API promises, lens geometry, the same frame as fl_write_polygon's pictures, rejected styles. */
#include "render_scenes.h"

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    size_t got = fread(s, 1, (size_t)n, f);
    s[got] = '\0';
    fclose(f);
    return s;
}

/* Minimal well-formedness: tags balance (a stack of names), attribute values are quoted, no
 * stray '<' or '&' in text, one root element <svg>. Returns 1 when well-formed. */
static int well_formed(const char *s)
{
    char stack[32][32];
    int depth = 0, roots = 0;
    for (const char *p = s; *p; p++) {
        if (*p == '&') return 0;
        if (*p != '<') continue;
        int closing = p[1] == '/';
        const char *name = p + 1 + closing;
        size_t len = strcspn(name, " \t\n/>");
        if (len == 0 || len >= 32) return 0;
        const char *q = name + len;
        while (*q && *q != '>') { /* attributes: name="value" */
            if (*q == '"') {
                const char *end = strchr(q + 1, '"');
                if (!end || memchr(q + 1, '<', (size_t)(end - q - 1))) return 0;
                q = end;
            } else if (*q == '<') {
                return 0;
            }
            q++;
        }
        if (!*q) return 0;
        int self = q[-1] == '/';
        if (closing) {
            if (depth == 0 || strncmp(stack[depth - 1], name, len) || stack[depth - 1][len])
                return 0;
            depth--;
        } else if (!self) {
            if (depth == 0) roots++;
            if (depth == 32) return 0;
            memcpy(stack[depth], name, len);
            stack[depth++][len] = '\0';
        }
        p = q;
    }
    return depth == 0 && roots == 1 && strncmp(s, "<svg", 4) == 0;
}

static size_t count_str(const char *s, const char *needle)
{
    size_t n = 0;
    for (const char *p = strstr(s, needle); p; p = strstr(p + 1, needle))
        n++;
    return n;
}

static void test_canvas_writes_every_item_well_formed(void)
{
    fl_svg *svg = NULL;
    fl_error err;
    CHECK_EQ_INT(fl_svg_new(0, &svg, &err), FL_OK);
    double pts[10] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    uint32_t edges[6] = {0, 1, 1, 2, 2, 4};
    double ctrl[14] = {0, 0, 0.2, 0.5, 0.8, 0.5, 1, 0, 1.2, -0.5, 1.5, -0.5, 2, 0};
    double d0[3] = {0, 0, 1}, d1[3] = {1.2, 0, 0.8};
    fl_svg_style red = {.stroke = "#b03a2e", .fill = "none", .stroke_width = 1, .opacity = 0.5};
    CHECK_EQ_INT(fl_svg_add_points(svg, pts, 5, NULL, &err), FL_OK);          /* 5 circles */
    CHECK_EQ_INT(fl_svg_add_polyline(svg, pts, 4, 1, &red, &err), FL_OK);     /* 1 path */
    CHECK_EQ_INT(fl_svg_add_edges(svg, pts, 5, edges, 3, NULL, &err), FL_OK); /* 1 path */
    CHECK_EQ_INT(fl_svg_add_disc(svg, 3, 3, 0.5, NULL, &err), FL_OK);         /* 1 circle */
    CHECK_EQ_INT(fl_svg_add_lens(svg, d0, d1, NULL, &err), FL_OK);            /* 1 path */
    CHECK_EQ_INT(fl_svg_add_bezier(svg, ctrl, 2, NULL, &err), FL_OK);         /* 1 path */
    /* A square with a square hole plus a triangle: two polygons, three rings. */
    double xy[22] = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 1, 3, 3, 3, 3, 1, 5, 0, 6, 0, 5, 1};
    size_t rs[4] = {0, 4, 8, 11}, ps[3] = {0, 2, 3};
    fl_polygon poly = {11, xy, 3, rs, 2, ps};
    CHECK_EQ_INT(fl_svg_add_polygon(svg, &poly, NULL, &err), FL_OK); /* 2 paths */
    CHECK_EQ_INT(fl_svg_element_count(svg), 12);
    CHECK_EQ_INT(fl_svg_write(svg, "render_canvas.svg", &err), FL_OK);
    char *s = slurp("render_canvas.svg");
    CHECK(s && well_formed(s));
    if (s) {
        CHECK_EQ_INT(count_str(s, "<circle"), 6);
        CHECK_EQ_INT(count_str(s, "<path"), 6);
        CHECK_EQ_INT(count_str(s, " C"), 2); /* two cubic segments */
        CHECK_EQ_INT(count_str(s, "evenodd"), 2);
        CHECK(strstr(s, "opacity=\"0.5\"") != NULL);
    }
    free(s);
    remove("render_canvas.svg");
    fl_svg_free(svg);
}

/* Centre of the SVG arc from (x1, y1) to (x2, y2) of radius r with the given flags (SVG 1.1
 * F.6.5 with rx = ry = r and no rotation). */
static void arc_center(double x1, double y1, double x2, double y2, double r, int large, int sweep,
                       double c[2])
{
    double xp = (x1 - x2) / 2, yp = (y1 - y2) / 2, l2 = xp * xp + yp * yp;
    double k = sqrt(fmax(0, (r * r - l2) / l2)) * (large != sweep ? 1 : -1);
    c[0] = k * yp + (x1 + x2) / 2;
    c[1] = -k * xp + (y1 + y2) / 2;
}

/* The lens boundary: both arc end points lie on both circles (in picture units), and each arc
 * bends around its own circle's centre. */
static void test_lens_arcs_meet_on_both_circles(void)
{
    fl_svg *svg = NULL;
    fl_error err;
    CHECK_EQ_INT(fl_svg_new(500, &svg, &err), FL_OK);
    double d0[3] = {0, 0, 1}, d1[3] = {0.9, 0.6, 0.7};
    CHECK_EQ_INT(fl_svg_add_disc(svg, d0[0], d0[1], d0[2], NULL, &err), FL_OK);
    CHECK_EQ_INT(fl_svg_add_disc(svg, d1[0], d1[1], d1[2], NULL, &err), FL_OK);
    CHECK_EQ_INT(fl_svg_add_lens(svg, d0, d1, NULL, &err), FL_OK);
    CHECK_EQ_INT(fl_svg_write(svg, "render_lens.svg", &err), FL_OK);
    char *s = slurp("render_lens.svg");
    double c[2][3];
    const char *p = s ? strstr(s, "<circle") : NULL;
    for (int k = 0; k < 2 && p; k++) {
        CHECK_EQ_INT(
            sscanf(p, "<circle cx=\"%lf\" cy=\"%lf\" r=\"%lf\"", &c[k][0], &c[k][1], &c[k][2]), 3);
        p = strstr(p + 1, "<circle");
    }
    const char *d = s ? strstr(s, "<path d=\"") : NULL;
    double px, py, r1a, r1b, qx, qy, r0a, r0b, ex, ey;
    int f1, s1, f0, s0, rot1, rot0;
    CHECK(d && sscanf(d, "<path d=\"M%lf %lf A%lf %lf %d %d %d %lf %lf A%lf %lf %d %d %d %lf %lf",
                      &px, &py, &r1a, &r1b, &rot1, &f1, &s1, &qx, &qy, &r0a, &r0b, &rot0, &f0, &s0,
                      &ex, &ey) == 16);
    if (d) {
        double pts[2][2] = {{px, py}, {qx, qy}};
        for (int i = 0; i < 2; i++)
            for (int k = 0; k < 2; k++)
                CHECK_NEAR(hypot(pts[i][0] - c[k][0], pts[i][1] - c[k][1]), c[k][2], 1e-3);
        CHECK_NEAR(r1a, c[1][2], 1e-3);
        CHECK_NEAR(r0a, c[0][2], 1e-3);
        /* Neither arc is the large one here: a = (d^2 + r0^2 - r1^2) / 2d lies in (0, d). */
        CHECK(f1 == 0 && f0 == 0);
        /* The centre SVG gives each arc (SVG 1.1 appendix F.6.5, equal radii, no rotation)
         * must be the centre of the circle the arc belongs to: circle 1, then circle 0. */
        double c1[2], c0[2];
        arc_center(px, py, qx, qy, r1a, f1, s1, c1);
        arc_center(qx, qy, ex, ey, r0a, f0, s0, c0);
        CHECK_NEAR(c1[0], c[1][0], 1e-2);
        CHECK_NEAR(c1[1], c[1][1], 1e-2);
        CHECK_NEAR(c0[0], c[0][0], 1e-2);
        CHECK_NEAR(c0[1], c[0][1], 1e-2);
    }
    free(s);
    remove("render_lens.svg");
    fl_svg_free(svg);
}

static void test_lens_of_nested_or_disjoint_discs(void)
{
    fl_svg *svg = NULL;
    fl_error err;
    CHECK_EQ_INT(fl_svg_new(0, &svg, &err), FL_OK);
    double big[3] = {0, 0, 2}, small[3] = {0.5, 0, 0.5}, away[3] = {10, 0, 1};
    CHECK_EQ_INT(fl_svg_add_lens(svg, big, small, NULL, &err), FL_OK); /* the small disc */
    CHECK_EQ_INT(fl_svg_element_count(svg), 1);
    CHECK_EQ_INT(fl_svg_add_lens(svg, big, away, NULL, &err), FL_OK); /* empty */
    CHECK_EQ_INT(fl_svg_element_count(svg), 1);
    CHECK_EQ_INT(fl_svg_write(svg, "render_nested.svg", &err), FL_OK);
    char *s = slurp("render_nested.svg");
    CHECK(s && well_formed(s) && count_str(s, "<circle") == 1 && count_str(s, "<path") == 0);
    free(s);
    remove("render_nested.svg");
    fl_svg_free(svg);
}

/* Disc-and-half-plane flintstones: the chord's ends lie on the circle and on the line, and
 * the arc back bends around the circle's own centre on both sides of the line. */
static void test_disc_halfplane_segments(void)
{
    for (int side = -1; side <= 1; side += 2) {
        fl_svg *svg = NULL;
        fl_error err;
        CHECK_EQ_INT(fl_svg_new(400, &svg, &err), FL_OK);
        double d[3] = {0.2, -0.1, 1}, a[2] = {-2, 0.3}, b[2] = {2, 0.3};
        CHECK_EQ_INT(fl_svg_add_disc(svg, d[0], d[1], d[2], NULL, &err), FL_OK);
        CHECK_EQ_INT(fl_svg_add_disc_halfplane(svg, d, a, b, side, NULL, &err), FL_OK);
        CHECK_EQ_INT(fl_svg_element_count(svg), 2);
        CHECK_EQ_INT(fl_svg_write(svg, "render_seg.svg", &err), FL_OK);
        char *s = slurp("render_seg.svg");
        double c[3], p[2], q[2], r, rb, e[2];
        int rot, large, sweep;
        const char *ci = s ? strstr(s, "<circle") : NULL, *pa = s ? strstr(s, "<path") : NULL;
        CHECK(ci &&
              sscanf(ci, "<circle cx=\"%lf\" cy=\"%lf\" r=\"%lf\"", &c[0], &c[1], &c[2]) == 3);
        CHECK(pa && sscanf(pa, "<path d=\"M%lf %lf L%lf %lf A%lf %lf %d %d %d %lf %lf", &p[0],
                           &p[1], &q[0], &q[1], &r, &rb, &rot, &large, &sweep, &e[0], &e[1]) == 11);
        if (ci && pa) {
            CHECK_NEAR(hypot(p[0] - c[0], p[1] - c[1]), c[2], 1e-3);
            CHECK_NEAR(hypot(q[0] - c[0], q[1] - c[1]), c[2], 1e-3);
            CHECK_NEAR(p[1], q[1], 1e-3);  /* the line y = 0.3 is horizontal in the picture */
            CHECK(p[1] < c[1]);            /* and above the centre (y down) */
            CHECK_EQ_INT(large, side < 0); /* the centre lies below the line: right of a -> b */
            double ac[2];
            arc_center(q[0], q[1], e[0], e[1], r, large, sweep, ac);
            CHECK_NEAR(ac[0], c[0], 1e-2);
            CHECK_NEAR(ac[1], c[1], 1e-2);
        }
        free(s);
        remove("render_seg.svg");
        /* A line missing the disc: the whole disc on one side, nothing on the other. */
        double fa[2] = {-2, 5}, fb[2] = {2, 5};
        size_t before = fl_svg_element_count(svg);
        CHECK_EQ_INT(fl_svg_add_disc_halfplane(svg, d, fa, fb, side, NULL, &err), FL_OK);
        CHECK_EQ_INT(fl_svg_element_count(svg), before + (side < 0));
        CHECK_EQ_INT(fl_svg_add_disc_halfplane(svg, d, fa, fa, side, NULL, &err), FL_ERR_INPUT);
        fl_svg_free(svg);
    }
}

/* A polygon drawn on the canvas lands on the same picture coordinates as in fl_write_polygon's
 * SVG (same frame: 1000 px longer side, 50 px margin, y up). */
static void test_polygon_frame_matches_io_svg_writer(void)
{
    double xy[8] = {-3, 1, 5, 1, 5, 2.5, -3, 4};
    size_t rs[2] = {0, 4}, ps[2] = {0, 1};
    fl_polygon poly = {4, xy, 1, rs, 1, ps};
    fl_error err;
    CHECK_EQ_INT(fl_write_polygon("render_io.svg", &poly, &err), FL_OK);
    fl_svg *svg = NULL;
    CHECK_EQ_INT(fl_svg_new(1000, &svg, &err), FL_OK);
    CHECK_EQ_INT(fl_svg_add_polygon(svg, &poly, NULL, &err), FL_OK);
    CHECK_EQ_INT(fl_svg_write(svg, "render_poly.svg", &err), FL_OK);
    char *a = slurp("render_io.svg"), *b = slurp("render_poly.svg");
    const char *pa = a ? strstr(a, "d=\"M") : NULL, *pb = b ? strstr(b, "d=\"M") : NULL;
    CHECK(pa && pb);
    if (pa && pb) {
        size_t la = strcspn(pa + 3, "\""), lb = strcspn(pb + 3, "\"");
        CHECK(la == lb && strncmp(pa + 3, pb + 3, la) == 0);
    }
    CHECK(b && well_formed(b));
    free(a);
    free(b);
    remove("render_io.svg");
    remove("render_poly.svg");
    fl_svg_free(svg);
}

static void test_bad_styles_and_data_are_rejected(void)
{
    fl_svg *svg = NULL;
    fl_error err;
    CHECK_EQ_INT(fl_svg_new(0, &svg, &err), FL_OK);
    double pts[4] = {0, 0, 1, NAN};
    fl_svg_style evil = {.stroke = "red\"/><script>"};
    CHECK_EQ_INT(fl_svg_add_points(svg, pts, 1, &evil, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_svg_add_points(svg, pts, 2, NULL, &err), FL_ERR_INPUT);
    uint32_t e[2] = {0, 5};
    CHECK_EQ_INT(fl_svg_add_edges(svg, pts, 2, e, 1, NULL, &err), FL_ERR_INPUT);
    CHECK_EQ_INT(fl_svg_add_disc(svg, 0, 0, -1, NULL, &err), FL_ERR_INPUT);
    CHECK_EQ_INT(fl_svg_add_bezier(svg, pts, 0, NULL, &err), FL_ERR_USAGE);
    size_t rs[2] = {0, 9}, ps[2] = {0, 1};
    fl_polygon bad = {2, pts, 1, rs, 1, ps};
    CHECK_EQ_INT(fl_svg_add_polygon(svg, &bad, NULL, &err), FL_ERR_INPUT);
    CHECK_EQ_INT(fl_svg_element_count(svg), 0);
    fl_svg_free(svg);
    CHECK_EQ_INT(fl_svg_new(1, &svg, &err), FL_ERR_USAGE);
    CHECK(svg == NULL);
}

FL_TEST_MAIN(FL_TEST_CASE(test_canvas_writes_every_item_well_formed),
             FL_TEST_CASE(test_lens_arcs_meet_on_both_circles),
             FL_TEST_CASE(test_lens_of_nested_or_disjoint_discs),
             FL_TEST_CASE(test_disc_halfplane_segments),
             FL_TEST_CASE(test_polygon_frame_matches_io_svg_writer),
             FL_TEST_CASE(test_bad_styles_and_data_are_rejected))

/* Exact intersection decisions from orientation signs only. No coordinates are constructed:
 * every branch is decided by fl_orient2d / fl_orient3d, so the answers are exact and the
 * degenerate cases (touching, collinear, coplanar) are answered like the general ones. */
#include "core/core.h"
#include "mesh/intersect.h"

/* Sign of det[a-c; b-c; d-c]: positive when d lies on the side of plane abc from which abc
 * is seen counter-clockwise ("above"). Shewchuk's orient3d has the opposite sign. */
static int side(const double *a, const double *b, const double *c, const double *d)
{
    return -fl_orient3d(a, b, c, d);
}

/* Axis-plane projection `axis` (0: xy, 1: yz, 2: zx) of p into out. */
static void project(const double *p, int axis, double *out)
{
    out[0] = p[axis];
    out[1] = p[(axis + 1) % 3];
}

/* An axis plane on which triangle abc projects to a proper triangle, or -1 when abc is
 * degenerate: the normal (b-a) x (c-a) has some nonzero component iff one projection has
 * a nonzero orient2d, and that projection is then one-to-one on the triangle's plane. */
static int proper_projection(const double *a, const double *b, const double *c)
{
    for (int axis = 0; axis < 3; axis++) {
        double pa[2], pb[2], pc[2];
        project(a, axis, pa);
        project(b, axis, pb);
        project(c, axis, pc);
        if (fl_orient2d(pa, pb, pc) != 0) return axis;
    }
    return -1;
}

int fl_triangle_degenerate(const double *a, const double *b, const double *c)
{
    return proper_projection(a, b, c) < 0;
}

static int in_box2(const double *a, const double *b, const double *c, const double *d)
{
    for (int k = 0; k < 2; k++) {
        double lo1 = a[k] < b[k] ? a[k] : b[k], hi1 = a[k] < b[k] ? b[k] : a[k];
        double lo2 = c[k] < d[k] ? c[k] : d[k], hi2 = c[k] < d[k] ? d[k] : c[k];
        if (hi1 < lo2 || hi2 < lo1) return 0;
    }
    return 1;
}

int fl_segments_intersect2(const double *a, const double *b, const double *c, const double *d)
{
    int o1 = fl_orient2d(a, b, c), o2 = fl_orient2d(a, b, d);
    if (o1 * o2 > 0) return 0;
    int o3 = fl_orient2d(c, d, a), o4 = fl_orient2d(c, d, b);
    if (o3 * o4 > 0) return 0;
    /* c and d both on line ab: the segments are collinear (or ab is a point on line cd),
     * and collinear segments meet iff their boxes do. Otherwise the lines cross once and the
     * sign conditions put that point on both segments. */
    if (o1 == 0 && o2 == 0) return in_box2(a, b, c, d);
    return 1;
}

/* Closed 2D point-in-triangle; t is a proper triangle. */
static int point_in_triangle2(const double *x, const double *t0, const double *t1, const double *t2)
{
    int o = fl_orient2d(t0, t1, t2);
    return fl_orient2d(t0, t1, x) * o >= 0 && fl_orient2d(t1, t2, x) * o >= 0 &&
           fl_orient2d(t2, t0, x) * o >= 0;
}

/* Closed segment ab and proper triangle pqr, all in one plane, projected on `axis`. */
static int coplanar_segment_triangle(const double *a, const double *b, const double *p,
                                     const double *q, const double *r, int axis)
{
    double A[2], B[2], t[3][2];
    project(a, axis, A);
    project(b, axis, B);
    project(p, axis, t[0]);
    project(q, axis, t[1]);
    project(r, axis, t[2]);
    if (point_in_triangle2(A, t[0], t[1], t[2])) return 1;
    for (int i = 0; i < 3; i++)
        if (fl_segments_intersect2(A, B, t[i], t[(i + 1) % 3])) return 1;
    return 0;
}

int fl_segment_triangle_intersect(const double *a, const double *b, const double *p,
                                  const double *q, const double *r)
{
    int sa = side(p, q, r, a), sb = side(p, q, r, b);
    if (sa * sb > 0) return 0;
    if (sa == 0 && sb == 0)
        return coplanar_segment_triangle(a, b, p, q, r, proper_projection(p, q, r));
    /* ab meets the plane in exactly one point; it lies in the closed triangle iff the line
     * ab passes on the same side of all three edge lines (signed tetrahedron volumes of
     * Plücker type; a zero means through an edge or vertex). */
    int s1 = side(a, b, p, q), s2 = side(a, b, q, r), s3 = side(a, b, r, p);
    int pos = s1 > 0 || s2 > 0 || s3 > 0, neg = s1 < 0 || s2 < 0 || s3 < 0;
    return !(pos && neg);
}

/* Two proper coplanar triangles meet iff an edge of one meets an edge of the other or one
 * contains a vertex of the other (then it contains the other entirely). */
static int coplanar_triangles(const double *const t1[3], const double *const t2[3])
{
    int axis = proper_projection(t1[0], t1[1], t1[2]);
    double a[3][2], b[3][2];
    for (int i = 0; i < 3; i++)
        project(t1[i], axis, a[i]), project(t2[i], axis, b[i]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (fl_segments_intersect2(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3])) return 1;
    return point_in_triangle2(a[0], b[0], b[1], b[2]) || point_in_triangle2(b[0], a[0], a[1], a[2]);
}

static int all_strictly_same(const int *s)
{
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}

/* Guigue–Devillers canonical form: the apex is the vertex alone on its (closed) side of the
 * other plane, with the other two on the opposite closed side and not all three on the plane
 * but the apex. Returns the apex index and whether the other plane must be reversed so the
 * apex is on the positive side. Callers have excluded "all strictly one side" and "all 0". */
static void pick_apex(const int *s, int *apex, int *flip)
{
    for (int i = 0; i < 3; i++) {
        int a = s[i], b = s[(i + 1) % 3], c = s[(i + 2) % 3];
        if (a != 0 && a * b <= 0 && a * c <= 0) {
            *apex = i, *flip = a < 0;
            return;
        }
    }
    /* remaining pattern: one vertex on the plane, the other two strictly on one side */
    for (int i = 0; i < 3; i++) {
        int b = s[(i + 1) % 3];
        if (s[i] == 0 && b == s[(i + 2) % 3]) {
            *apex = i, *flip = b > 0;
            return;
        }
    }
}

static void rotate(const double *t[3], int *s, int k)
{
    const double *p = t[k], *q = t[(k + 1) % 3], *r = t[(k + 2) % 3];
    int sp = s[k], sq = s[(k + 1) % 3], sr = s[(k + 2) % 3];
    t[0] = p, t[1] = q, t[2] = r;
    s[0] = sp, s[1] = sq, s[2] = sr;
}

static void swap_last_two(const double *t[3], int *s)
{
    const double *p = t[1];
    t[1] = t[2], t[2] = p;
    if (s) {
        int x = s[1];
        s[1] = s[2], s[2] = x;
    }
}

int fl_triangles_intersect(const double *p1, const double *q1, const double *r1, const double *p2,
                           const double *q2, const double *r2)
{
    const double *t1[3] = {p1, q1, r1}, *t2[3] = {p2, q2, r2};
    int s1[3], s2[3], apex, flip;
    for (int i = 0; i < 3; i++)
        s1[i] = side(p2, q2, r2, t1[i]);
    if (all_strictly_same(s1)) return 0;
    if (s1[0] == 0 && s1[1] == 0 && s1[2] == 0) return coplanar_triangles(t1, t2);
    for (int i = 0; i < 3; i++)
        s2[i] = side(p1, q1, r1, t2[i]);
    if (all_strictly_same(s2)) return 0;
    /* Each triangle meets the line L of the two planes in an interval; put each in canonical
     * form (apex above the other plane, the rest below) so that both intervals start on the
     * apex's first edge and end on its last (Guigue & Devillers 2003, §3). */
    pick_apex(s1, &apex, &flip);
    rotate(t1, s1, apex);
    if (flip) swap_last_two(t2, s2);
    pick_apex(s2, &apex, &flip);
    rotate(t2, s2, apex);
    if (flip) swap_last_two(t1, NULL);
    /* The intervals overlap iff neither ends before the other starts; both comparisons are
     * orientations of the apexes with one edge endpoint from each triangle. */
    return side(t2[0], t1[0], t1[1], t2[1]) <= 0 && side(t2[0], t1[2], t1[0], t2[2]) <= 0;
}

int fl_triangles_meet_beyond_vertex(const double *v, const double *a, const double *b,
                                    const double *c, const double *d)
{
    return fl_segment_triangle_intersect(a, b, v, c, d) ||
           fl_segment_triangle_intersect(c, d, v, a, b);
}

int fl_triangles_fold_over(const double *u, const double *v, const double *a, const double *b)
{
    /* Side test first, in a projection where uva is proper: when the triangles are coplanar
     * it is their side in the plane; when they are not, the answer is "no" whatever it says.
     * Adjacent mesh triangles lie on opposite sides, so the (often near-zero, hence slow)
     * coplanarity test is rarely needed. */
    int axis = proper_projection(u, v, a);
    double U[2], V[2], A[2], B[2];
    project(u, axis, U);
    project(v, axis, V);
    project(a, axis, A);
    project(b, axis, B);
    if (fl_orient2d(U, V, A) * fl_orient2d(U, V, B) <= 0) return 0;
    return fl_orient3d(u, v, a, b) == 0;
}

/* Exact intersection tests on closed segments and triangles, built only from the signs of
 * fl_orient2d and fl_orient3d (so every answer is exact for all finite doubles). Internal;
 * reusable by HAL and sweep. Triangles passed to the triangle tests must be non-degenerate
 * (fl_triangle_degenerate() == 0). */
#ifndef FL_MESH_INTERSECT_H
#define FL_MESH_INTERSECT_H

/* 1 iff the three points are collinear (or coincide): the cross product (b-a) x (c-a) is the
 * zero vector, i.e. all three axis projections have orient2d == 0. */
int fl_triangle_degenerate(const double *a, const double *b, const double *c);

/* 1 iff closed 2D segments [a,b] and [c,d] have a common point. Points are double[2]. */
int fl_segments_intersect2(const double *a, const double *b, const double *c, const double *d);

/* 1 iff the closed 3D segment [a,b] meets the closed triangle pqr. */
int fl_segment_triangle_intersect(const double *a, const double *b, const double *p,
                                  const double *q, const double *r);

/* 1 iff closed triangles p1q1r1 and p2q2r2 have a common point (Guigue & Devillers 2003,
 * orientation-only formulation). */
int fl_triangles_intersect(const double *p1, const double *q1, const double *r1, const double *p2,
                           const double *q2, const double *r2);

/* Triangles vab and vcd share exactly the vertex v (all five points distinct positions of a
 * mesh, both triangles proper). 1 iff they have a common point other than v. That is the case
 * iff segment ab meets triangle vcd or segment cd meets triangle vab: the intersection is
 * convex and contains v, so if it is more than v it has an extreme point other than v, and
 * following the boundary from there reaches ab or cd inside the other triangle. */
int fl_triangles_meet_beyond_vertex(const double *v, const double *a, const double *b,
                                    const double *c, const double *d);

/* Proper triangles uva and uvb share the edge uv. 1 iff they overlap beyond it: they are
 * coplanar and a, b lie on the same side of line uv. (Non-coplanar, their planes meet only in
 * the line uv, which meets each triangle only in the edge.) */
int fl_triangles_fold_over(const double *u, const double *v, const double *a, const double *b);

#endif /* FL_MESH_INTERSECT_H */

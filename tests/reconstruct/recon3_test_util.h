/* Independent checks of a 3D reconstruction (thesis §5.3): fl_mesh_check for closedness,
 * manifoldness, orientation and genus; the free faces of the interior tetrahedra recomputed from
 * scratch and compared with the boundary; the enclosed volume by the divergence theorem; the
 * points on the boundary recounted. Shared by the tests/reconstruct/test_constrict3*.c. */
#ifndef RECON3_TEST_UTIL_H
#define RECON3_TEST_UTIL_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"

typedef struct face_key {
    uint32_t v[3]; /* rotated so that the smallest index comes first; orientation kept */
} face_key;

static inline face_key make_face(uint32_t a, uint32_t b, uint32_t c)
{
    face_key f;
    if (a < b && a < c)
        f = (face_key){{a, b, c}};
    else if (b < c)
        f = (face_key){{b, c, a}};
    else
        f = (face_key){{c, a, b}};
    return f;
}

/* the same face seen from the other side */
static inline face_key flip_face(face_key f)
{
    return make_face(f.v[0], f.v[2], f.v[1]);
}

static inline int face_lt(face_key a, face_key b)
{
    for (int i = 0; i < 3; i++)
        if (a.v[i] != b.v[i]) return a.v[i] < b.v[i];
    return 0;
}

static inline int face_cmp(const void *x, const void *y)
{
    const face_key *a = x, *b = y;
    return face_lt(*a, *b) ? -1 : face_lt(*b, *a);
}

/* The faces of the tetrahedra that no other tetrahedron shares (with opposite orientation),
 * sorted; *count receives how many. Face opposite corner k as in include/flintstone.h. */
static inline face_key *free_faces(const fl_reconstruction3 *r, size_t *count)
{
    static const int fc[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
    size_t m = 4 * r->tet_count;
    face_key *all = malloc((m ? m : 1) * sizeof *all);
    face_key *outf = malloc((m ? m : 1) * sizeof *outf);
    for (size_t t = 0; t < r->tet_count; t++)
        for (int k = 0; k < 4; k++) {
            const uint32_t *c = r->tet + 4 * t;
            all[4 * t + k] = make_face(c[fc[k][0]], c[fc[k][1]], c[fc[k][2]]);
        }
    qsort(all, m, sizeof *all, face_cmp);
    size_t n = 0;
    for (size_t i = 0; i < m; i++) {
        face_key fl = flip_face(all[i]);
        size_t lo = 0, hi = m; /* binary search for the flipped face */
        while (lo < hi) {
            size_t mid = (lo + hi) / 2;
            if (face_lt(all[mid], fl))
                lo = mid + 1;
            else
                hi = mid;
        }
        if (lo == m || memcmp(&all[lo], &fl, sizeof fl) != 0) outf[n++] = all[i];
    }
    free(all);
    *count = n;
    return outf;
}

/* Checks every property the contract promises; returns the mesh report's volume. */
static inline double check_reconstruction_si(const double *xyz, size_t n,
                                             const fl_reconstruction3 *r, int self_intersections)
{
    fl_mesh mesh = {n, (double *)(uintptr_t)xyz, r->triangle_count, r->tri};
    fl_mesh_check_options mopt = {0};
    mopt.skip_self_intersections = !self_intersections;
    fl_mesh_report rep;
    fl_error err;
    CHECK_STATUS(fl_mesh_check(&mesh, &mopt, &rep, &err), FL_OK, &err);
    CHECK(rep.closed);
    CHECK(rep.manifold);
    CHECK(rep.oriented);
    CHECK_EQ_INT(rep.components, 1);
    CHECK_EQ_INT(rep.genus, 0);
    CHECK_EQ_INT(rep.degenerate_faces, 0);
    if (rep.self_intersections_checked) CHECK_EQ_INT(rep.self_intersections, 0);
    CHECK(r->volume > 0);
    CHECK_NEAR(rep.volume, r->volume, 1e-9 * (1 + fabs(r->volume)));
    double volume = rep.volume;
    fl_mesh_report_free(&rep);

    /* boundary = free faces of the interior tetrahedra, orientation included */
    size_t nf = 0;
    face_key *ff = free_faces(r, &nf);
    CHECK_EQ_INT(nf, r->triangle_count);
    face_key *bt = malloc((r->triangle_count + 1) * sizeof *bt);
    for (size_t i = 0; i < r->triangle_count; i++)
        bt[i] = make_face(r->tri[3 * i], r->tri[3 * i + 1], r->tri[3 * i + 2]);
    qsort(bt, r->triangle_count, sizeof *bt, face_cmp);
    if (nf == r->triangle_count) CHECK(memcmp(ff, bt, nf * sizeof *ff) == 0);
    free(ff);
    free(bt);

    /* the points on the boundary are exactly the distinct points not reported inside */
    unsigned char *on = calloc(n, 1);
    for (size_t i = 0; i < 3 * r->triangle_count; i++)
        on[r->tri[i]] = 1;
    size_t on_count = 0;
    for (size_t i = 0; i < n; i++)
        on_count += on[i];
    CHECK_EQ_INT(on_count, r->boundary_vertex_count);
    CHECK_EQ_INT(on_count + r->points_inside, r->unique_count);
    for (size_t i = 0; i < r->points_inside; i++)
        CHECK(!on[r->inside[i]]);
    CHECK_EQ_INT(r->all_on_boundary, r->points_inside == 0 && r->keep_missing == 0);
    CHECK((r->reason[0] == 0) == (r->all_on_boundary == 1));
    /* every 2-3 flip turns two tetrahedra into three */
    CHECK_EQ_INT(r->tet_count + r->removed_count, r->delaunay_tet_count + r->flip_count);
    CHECK_EQ_INT(r->flip_count == 0, isnan(r->augmented_c0));
    free(on);
    return volume;
}

/* The same, with the self-intersection search for small inputs only. */
static inline double check_reconstruction(const double *xyz, size_t n, const fl_reconstruction3 *r)
{
    return check_reconstruction_si(xyz, n, r, n <= 400);
}

#endif /* RECON3_TEST_UTIL_H */

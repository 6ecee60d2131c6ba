/* Certified Hausdorff distance (Guéziec 2001, §6): the state of one direction h(A,B), i.e.
 * samples on the simplices (triangles or segments) of A and their closest points on B found
 * through a Meshsweeper cursor. Shared by hausdorff.c (set-up, public API), hausdorff_refine.c
 * (upper bounds and refinement) and hausdorff_field.c (field output). */
#ifndef FL_HAUSDORFF_INTERNAL_H
#define FL_HAUSDORFF_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "core/core.h"
#include "flintstone.h"

/* A point of A where the distance to B was measured: p on A, c its closest point on B (on
 * element `elem` of B), d = |p - c|. 2D shapes have z = 0. */
typedef struct hd_sample {
    double p[3], c[3];
    double d;
    uint32_t elem;
    uint32_t exact; /* 1: c is B's closest point (a cursor query); 0: c is only some point of
                     * B (the nearest on a few candidate elements), so d >= d(p, B) */
} hd_sample;

/* A simplex of the refinement of A: corners are sample indices (k = 3 for triangles, 2 for
 * segments; v[2] unused then), `upper` its proven bound on max d(x, B) over x in it. */
typedef struct hd_simplex {
    uint32_t v[3];
    uint32_t tried; /* 1 once the element at the closest points' centroid was tried */
    double upper;
} hd_simplex;

/* The limits shared by both directions. */
typedef struct hd_run {
    double precision;    /* absolute */
    double scale;        /* largest |coordinate| of both shapes, for rounding slack */
    double min_edge;     /* simplices whose longest edge is shorter are not split */
    double deadline;     /* monotonic seconds; 0 = none */
    size_t max_samples;  /* over both directions */
    size_t samples;      /* queries so far, both directions */
    size_t splits;       /* splits so far: the clock is read every 64 */
    int both_directions; /* refine each direction to precision, not only the maximum */
    int keep_field;      /* record leaves for the field */
    int exhausted;       /* budget or sample cap reached */
    fl_progress_fn progress;
    void *progress_user;
    double progress_done; /* fraction of all initial simplices finished, both directions */
    double progress_total;
} hd_run;

/* One direction h(A,B). */
typedef struct hd_dir {
    int k;                   /* corners of a simplex: 3 (meshes) or 2 (polylines) */
    int dim;                 /* query dimension of the cursor: 2 or 3 */
    fl_sweep_cursor *cursor; /* on B */
    const double *b_xyz;     /* B's vertices (3D) and simplices (k indices each), for the */
    const uint32_t *b_idx;   /* fixed-element bound */
    uint32_t *b_adj;         /* k neighbours of each element of B across its edges (triangles)
                              * or ends (segments), FL_SWEEP_NONE where none: candidates */
    fl_vec samples;          /* hd_sample; the first ones are A's vertices */
    uint32_t *used;          /* 1 for vertices of A used by a simplex */
    hd_simplex *simplices;   /* A's own simplices, with their initial bounds */
    size_t simplex_count;
    fl_vec leaves;         /* hd_simplex: the final refinement (keep_field only) */
    double lower;          /* largest measured distance (minus slack) */
    uint32_t lower_sample; /* where */
    double upper;          /* max bound of the simplices finished or pending */
} hd_dir;

/* Monotonic clock in seconds. */
double hd_now(void);

/* Builds dir->b_adj for B's k-corner elements (ns of them, indices idx). */
fl_status hd_adjacency(hd_dir *dir, const uint32_t *idx, size_t ns, fl_error *err);

/* Measures the sample at p (3 doubles) with the cursor and appends it; updates dir->lower.
 * Returns its index through *index. */
fl_status hd_measure(hd_run *run, hd_dir *dir, const double *p, uint32_t *index, fl_error *err);

/* Updates dir->lower with sample `index` when it is exact. */
void hd_note_sample(hd_run *run, hd_dir *dir, uint32_t index);

/* The sample at p into *out: from the elements of samples near[0..n) (n <= 3) and their
 * neighbours when that point of B is within dir->lower (inexact), else a cursor query. Does
 * not store it; the caller stores it and calls hd_note_sample. */
fl_status hd_sample_near(hd_run *run, hd_dir *dir, const double *p, const uint32_t *near, int n,
                         hd_sample *out, fl_error *err);

/* The proven upper bound of max_{x in s} d(x, B) over a simplex (see hausdorff_refine.c);
 * bound (1) alone once it is <= enough (pass 0 for the tightest). */
double hd_simplex_bound(const hd_run *run, const hd_dir *dir, const hd_simplex *s, double enough);

/* Bound (2) with one more candidate element: the one closest to the centroid of the corners'
 * closest points (when those lie on an edge or vertex of B, the elements the corners reported
 * may each miss some of them). Lowers s->upper when it applies. */
fl_status hd_try_centroid_element(hd_run *run, hd_dir *dir, hd_simplex *s, fl_error *err);

/* Refines direction `dir` until every simplex bound is <= threshold + precision, where the
 * threshold is dir->lower (both_directions) or max(dir->lower, *other_lower) otherwise; stops
 * early on the budget. Sets dir->upper. */
fl_status hd_refine(hd_run *run, hd_dir *dir, const double *other_lower, fl_error *err);

/* Builds a result field from a direction's samples and leaves. */
fl_status hd_field_from_dir(const hd_dir *dir, fl_hausdorff_field *field, fl_error *err);

#endif /* FL_HAUSDORFF_INTERNAL_H */

/* Internal interface between the two halves of the 3D shortest-edge search (docs/gamma.md,
 * "Construction", 3D): gamma3_edges.c (the per-pair lens scan and the exact checks) and
 * gamma3_cells.c (the cell-pair certificate that drops whole groups of far pairs at once,
 * "Certifying far cell pairs"). Not part of the public API. */
#ifndef FL_GAMMA3_SEARCH_H
#define FL_GAMMA3_SEARCH_H

#include "graphs/gamma_internal.h"

/* Which vertex pairs go through the per-pair scan. */
typedef enum gamma3_pairs {
    GAMMA3_ALL_PAIRS = 0, /* every one of the N(N-1)/2 pairs */
    GAMMA3_CELL_PAIRS = 1, /* a dual-tree recursion; certified cell pairs are skipped */
    /* Flag to OR in: each pair goes straight to the ring scan (no quick drop test), i.e. the
     * search of round 9, kept as the reference the tests compare the default with. */
    GAMMA3_PLAIN_SCAN = 2,
    /* Flag to OR in: no witness reuse (docs/gamma.md, "Round 11: witness reuse"): the pairs in
     * index order, each starting with the quick drop test, i.e. the default of round 10. */
    GAMMA3_NO_WITNESS = 4
} gamma3_pairs;

/* What gamma3_edge_triangles uses (docs/gamma.md, "Certifying far cell pairs"). */
#define GAMMA3_DEFAULT_PAIRS GAMMA3_ALL_PAIRS

/* Counters of one search (for tests and measurements). */
typedef struct gamma3_stats {
    size_t pairs_scanned;   /* pairs handed to the per-pair scan */
    size_t pairs_certified; /* pairs inside certified cell pairs (never scanned) */
    size_t cert_tries, cert_ok;
    size_t cert_visits;     /* points looked at by the certificates */
    size_t witness_dropped; /* pairs dropped by the cached witnesses of earlier pairs */
    size_t witness_visits;  /* cached witnesses tested */
    size_t quick_dropped;   /* pairs dropped by the quick drop test */
    size_t quick_visits;    /* points the quick drop test looked at */
    size_t scan_dropped;    /* pairs dropped by the ring scan */
    size_t scan_kept;       /* pairs whose candidates went to the exact check */
    size_t scan_visits;     /* points the ring scan saw (dropped and kept pairs) */
    size_t kd_walks;        /* pairs whose scan went on in the kd-tree (kd_scan) */
    size_t candidates;      /* triangles handed to the exact check */
} gamma3_stats;

/* gamma3_edge_triangles with an explicit pair strategy; stats may be NULL. */
fl_status gamma3_edge_triangles_with(const graph_grid *grid, const fl_gamma_params *p,
                                     double kappa, const fl_graph_options *opt,
                                     gamma3_pairs pairs, graph_builder *b, gamma3_stats *stats,
                                     fl_error *err);

/* atan2(y, x) within 1e-5 rad for finite (x, y) != (0, 0) (the quick drop test's angles). */
double gamma3_quick_angle(double x, double y);

/* An orthonormal frame (e, u1, u2) around the unit vector e (shared by both halves). */
void gamma3_frame(const double *e, double *u1, double *u2);

/* A kd-tree of the points (gamma3_cells.c): median splits of the longest box side, leaves of at
 * most 8 points; node 0 is the root, a node's children are child and child + 1 (child = 0 for a
 * leaf), its points perm[begin .. end-1] lie in the box [lo, hi] of half-diagonal r. */
typedef struct gamma3_kd_node {
    double lo[3], hi[3], r;
    uint32_t begin, end, child;
} gamma3_kd_node;

typedef struct gamma3_kdtree {
    const double *xyz;
    uint32_t *perm;
    gamma3_kd_node *nodes;
    size_t count;
} gamma3_kdtree;

/* Builds the tree of the n finite points xyz (kept by reference); 0, or -1 out of memory. */
int gamma3_kdtree_build(gamma3_kdtree *t, const double *xyz, size_t n);
void gamma3_kdtree_free(gamma3_kdtree *t);

/* gamma_triangle_check over the kd-tree of the points instead of the grid's rings (the same
 * decision and summary, gamma_triangles.c); `stack` is scratch (uint32_t). */
int gamma_triangle_check_kd(const gamma3_kdtree *kd, const fl_gamma_params *p, double kappa,
                            const uint32_t *t, fl_vec *stack, graph_builder *b);

/* Per-pair callback of the recursion: 0 to go on, -1 out of memory. */
typedef int (*gamma3_pair_fn)(void *ctx, uint32_t a, uint32_t b);

/* Hands every unordered pair of distinct points of the grid to fn exactly once, except the
 * pairs of cell pairs that gamma3_cell_certify proves to be no triangle's shortest edge. */
fl_status gamma3_cell_pairs(const graph_grid *grid, double s, gamma3_pair_fn fn, void *ctx,
                            gamma3_stats *stats, fl_error *err);

/* The certificate for the boxes A = [loA, hiA], B = [loB, hiB] (docs/gamma.md, Lemma C): 1 when
 * no pair a in A, b in B is the shortest edge of a triangle whose lens N_γ(-κ,-κ) is empty
 * (s = sqrt(g^2 - 1), g = 1/(1-κ)); 0 when that is not proved. `uncertainty` scales the
 * direction and midpoint uncertainty of the cell pair: 1 is the proved certificate; the tests
 * pass 0 to show that they catch a certificate without it. *visits (may be NULL) is increased
 * by the points looked at. */
int gamma3_cell_certify(const graph_grid *grid, double s, const double *loA, const double *hiA,
                        const double *loB, const double *hiB, double uncertainty, size_t *visits);

#endif /* FL_GAMMA3_SEARCH_H */

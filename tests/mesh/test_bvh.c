/* The box tree (src/mesh/bvh.h): its pair search against all pairs of boxes, its shape. */
#include "fl_test.h"
#include "mesh/bvh.h"

typedef struct pair_set {
    unsigned char *seen; /* n * n */
    size_t n, reported, repeated;
} pair_set;

static int record_pair(void *user, uint32_t a, uint32_t b)
{
    pair_set *s = user;
    unsigned char *cell = &s->seen[(a < b ? a : b) * s->n + (a < b ? b : a)];
    s->repeated += *cell;
    *cell = 1;
    s->reported++;
    return 0;
}

static int overlap(const double *a, const double *b)
{
    for (int k = 0; k < 3; k++)
        if (a[k] > b[3 + k] || b[k] > a[3 + k]) return 0;
    return 1;
}

/* Boxes on a grid of small integers (exact in float): reported pairs are exactly the
 * overlapping (touching included) pairs, each once. */
static void test_self_pairs_are_exactly_the_overlapping_boxes(void)
{
    unsigned long long rng = 51;
    size_t n = 700;
    double *boxes = malloc(6 * n * sizeof(double));
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            double lo = (double)(fl_test_rand_u64(&rng) % 20);
            boxes[6 * i + k] = lo;
            boxes[6 * i + 3 + k] = lo + (double)(fl_test_rand_u64(&rng) % 4);
        }
    fl_bvh bvh;
    fl_error err;
    CHECK_STATUS(fl_bvh_build(boxes, NULL, n, 4, &bvh, &err), FL_OK, &err);
    pair_set s = {calloc(n * n, 1), n, 0, 0};
    CHECK_EQ_INT(fl_bvh_self_pairs(&bvh, record_pair, &s, NULL, NULL, NULL), 0);
    size_t expect = 0, missing = 0;
    for (size_t a = 0; a < n; a++)
        for (size_t b = a + 1; b < n; b++) {
            int o = overlap(boxes + 6 * a, boxes + 6 * b);
            expect += (size_t)o;
            missing += o && !s.seen[a * n + b];
        }
    CHECK_EQ_INT(s.reported, expect);
    CHECK_EQ_INT(missing, 0);
    CHECK_EQ_INT(s.repeated, 0);
    CHECK(expect > 1000);
    free(s.seen);
    fl_bvh_free(&bvh);
    free(boxes);
}

static int depth_of(const fl_bvh *bvh, uint32_t node)
{
    const fl_bvh_node *nd = &bvh->nodes[node];
    if (nd->count) return 1;
    int l = depth_of(bvh, nd->left), r = depth_of(bvh, nd->left + 1);
    return 1 + (l > r ? l : r);
}

/* The edges of a comb polygon (a long base, then teeth in descending x) made median-of-three
 * quickselect quadratic; the build must stay fast and balanced, every primitive in exactly one
 * leaf and inside its node's box. */
static void test_comb_edges_build_a_balanced_tree(void)
{
    size_t teeth = 100000, n = 2 * teeth + 3, k = 0;
    double *xy = malloc(2 * n * sizeof(double)), *boxes = malloc(6 * n * sizeof(double));
    xy[2 * k] = 0, xy[2 * k + 1] = 0, k++;
    xy[2 * k] = (double)teeth, xy[2 * k + 1] = 0, k++;
    for (size_t i = teeth; i-- > 0;) {
        xy[2 * k] = (double)i + 1, xy[2 * k + 1] = 1, k++;
        xy[2 * k] = (double)i + 0.5, xy[2 * k + 1] = 3, k++;
    }
    xy[2 * k] = 0, xy[2 * k + 1] = 1, k++;
    for (size_t i = 0; i < n; i++) {
        const double *a = xy + 2 * i, *b = xy + 2 * ((i + 1) % n);
        double box[6] = {fmin(a[0], b[0]), fmin(a[1], b[1]), 0,
                         fmax(a[0], b[0]), fmax(a[1], b[1]), 0};
        memcpy(boxes + 6 * i, box, sizeof box);
    }
    free(xy);
    fl_bvh bvh;
    fl_error err;
    CHECK_STATUS(fl_bvh_build(boxes, NULL, n, 4, &bvh, &err), FL_OK, &err);
    int depth = depth_of(&bvh, 0), bound = 1;
    while (((size_t)1 << (bound - 1)) * 2 < n)
        bound++; /* leaves hold >= 2 of 4 */
    CHECK_MSG(depth <= bound + 1, "depth %d, bound %d", depth, bound + 1);
    unsigned char *in_leaf = calloc(n, 1);
    int inside = 1;
    for (size_t m = 0; m < bvh.node_count; m++) {
        const fl_bvh_node *nd = &bvh.nodes[m];
        for (uint32_t i = nd->start; i < nd->start + nd->count; i++) {
            in_leaf[bvh.prim[i]]++;
            const double *b = boxes + 6 * (size_t)bvh.prim[i];
            for (int d = 0; d < 3; d++)
                inside &= nd->box[d] <= b[d] && b[3 + d] <= nd->box[3 + d];
        }
    }
    size_t once = 0;
    for (size_t i = 0; i < n; i++)
        once += in_leaf[i] == 1;
    CHECK_EQ_INT(once, n);
    CHECK(inside);
    free(in_leaf);
    fl_bvh_free(&bvh);
    free(boxes);
}

static void test_empty_tree_reports_nothing(void)
{
    fl_bvh bvh;
    fl_error err;
    CHECK_STATUS(fl_bvh_build(NULL, NULL, 0, 4, &bvh, &err), FL_OK, &err);
    pair_set s = {NULL, 0, 0, 0};
    CHECK_EQ_INT(fl_bvh_self_pairs(&bvh, record_pair, &s, NULL, NULL, NULL), 0);
    CHECK_EQ_INT(s.reported, 0);
    fl_bvh_free(&bvh);
}

FL_TEST_MAIN(FL_TEST_CASE(test_self_pairs_are_exactly_the_overlapping_boxes),
             FL_TEST_CASE(test_comb_edges_build_a_balanced_tree),
             FL_TEST_CASE(test_empty_tree_reports_nothing))

/* The picture of a 2D flintstone approximation (thesis Fig. 7.5-7.6): the polygon in grey, the
 * approximation in blue and, in orange, the flintstones of the polylines the approximation cuts
 * off - each the bounding area of one approximating edge. Shared by `hal -o X.svg` and the
 * demo/report pipeline. */
#include <math.h>
#include <stdlib.h>

#include "cli/commands.h"
#include "core/core.h"

typedef struct cut {
    const fl_hal2 *hal;
    int by_level;
    uint32_t level;
    double max_error;
} cut;

/* A polyline is cut off when its split vertex is not in the approximation: by level, when the
 * vertex appears only at a deeper level; adaptively, when the node's error is within bounds
 * (fl_hal2_approximate_error refines only nodes whose error exceeds it). */
static int is_cut(const cut *c, const fl_hal2_node *n)
{
    return c->by_level ? n->level > c->level : n->error <= c->max_error;
}

static fl_status draw_node(fl_svg *svg, const fl_hal2_node *n, const double *xy, fl_error *err)
{
    fl_svg_style stone = {"#b35806", "#fdb863", 1, 0.35, 0};
    double d0[3] = {n->disc[0][0], n->disc[0][1], sqrt(n->disc[0][2])};
    double d1[3] = {n->disc[1][0], n->disc[1][1], sqrt(n->disc[1][2])};
    if (n->kind == FL_HAL2_TWO_DISCS) return fl_svg_add_lens(svg, d0, d1, &stone, err);
    if (n->kind == FL_HAL2_DISC_HALFPLANE)
        return fl_svg_add_disc_halfplane(svg, d0, xy + 2 * n->p, xy + 2 * n->s, n->side, &stone,
                                         err);
    if (n->kind == FL_HAL2_DISC) return fl_svg_add_disc(svg, d0[0], d0[1], d0[2], &stone, err);
    return FL_OK; /* a collinear run lies on its approximating edge */
}

static fl_status visit(fl_svg *svg, const cut *c, int32_t node, fl_error *err)
{
    /* Depth is bounded by the tree's depth; trees of spirals are deep (docs/hal.md), so walk
     * with an explicit stack rather than recursion. */
    size_t cap = 64, top = 0;
    int32_t *stack = malloc(cap * sizeof *stack);
    if (!stack) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    fl_status st = FL_OK;
    if (node >= 0) stack[top++] = node;
    while (top && st == FL_OK) {
        const fl_hal2_node *n = &c->hal->nodes[stack[--top]];
        if (is_cut(c, n)) {
            st = draw_node(svg, n, c->hal->polygon.xy, err);
            continue;
        }
        for (int k = 0; k < 2; k++) {
            if (n->child[k] < 0) continue;
            if (top == cap) {
                int32_t *grown = realloc(stack, 2 * cap * sizeof *stack);
                if (!grown) {
                    st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
                    break;
                }
                stack = grown;
                cap *= 2;
            }
            stack[top++] = n->child[k];
        }
    }
    free(stack);
    return st;
}

fl_status cli_write_hal2_svg(const char *path, const fl_hal2 *hal, const fl_polygon *approx,
                             int by_level, uint32_t level, double max_error, fl_error *err)
{
    fl_svg *svg;
    fl_status st = fl_svg_new(900, &svg, err);
    if (st) return st;
    cut c = {hal, by_level, level, max_error};
    for (size_t r = 0; r < hal->polygon.ring_count && st == FL_OK; r++)
        for (int k = 0; k < 2 && st == FL_OK; k++) st = visit(svg, &c, hal->rings[r].child[k], err);
    fl_svg_style original = {"#5a5a5a", "none", 1, 0, 0};
    fl_svg_style approximation = {"#1f4e79", "none", 2.5, 0, 0};
    if (st == FL_OK) st = fl_svg_add_polygon(svg, &hal->polygon, &original, err);
    if (st == FL_OK) st = fl_svg_add_polygon(svg, approx, &approximation, err);
    if (st == FL_OK) st = fl_svg_write(svg, path, err);
    fl_svg_free(svg);
    return st;
}

/* Point location in the mixed complex: G(x) from one quadric instead of a candidate scan.
 *
 * Edelsbrunner's mixed cells mu_X = (1-t) X + t nu_X, X over the simplices of the regular
 * triangulation and nu_X its power face, tile R^3 for 0 < t < 1, and on mu_X the skin function
 * is X's quadric (skin_function.c, docs/skin.md "The skin function"). Writing x - f = p + q
 * (parallel / orthogonal to aff X, f the focus of X), x = (1-t) z + t v with z = f + p/(1-t)
 * in aff X and v = f + q/t in aff nu_X, so
 *     x in mu_X  <=>  z in X (barycentric coordinates >= 0)  and  v in nu_X.
 * nu_X is the convex polytope whose facets are the power faces of the cofaces X + b, b in the
 * link of X, so v in nu_X <=> pi_b(v) >= pi_X(v) for every link ball b (a linear test).
 * The facets of mu_X are (1-t) Y + t nu_X for the facets Y of X, shared with mu_Y, and
 * (1-t) X + t nu_{X+b}, shared with mu_{X+b}; so a violated test names the neighbouring cell
 * on the far side of it: drop the vertex with a negative barycentric coordinate, or add the
 * link ball b whose test fails. The mesher evaluates neighbouring points, so starting from the
 * previous point's cell the walk ends after 0-2 steps. A walk that does not end within its step
 * cap (degenerate power faces, rounding near a shared boundary), comes back to a cell it left,
 * or cannot go round a simplex that was dropped as affinely dependent first tries the cells
 * round the one it stopped in (give_up_search), then falls back to the candidate scan, which
 * is correct on its own; so the walk only changes the speed, never the
 * value beyond rounding. The mesher's function crosses the cells of its simplices of
 * non-positive balls through light records (skin_light, frame recomputed on entry). */
#include <math.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "skin/skin_internal.h"

/* Relative slack of the membership tests: x within it of mu_X is accepted (the quadrics of
 * neighbouring cells agree on their common boundary, G is C^1, so the value differs from G by
 * rounding-sized amounts), which also keeps two neighbours from both rejecting a boundary point. */
#define SKIN_WALK_SLACK 1e-12
/* Steps from the caller's start, then from the index cell's first simplex. The second was 96
 * until round 12: on sphere.off's B* (eps 0.3) 2760 walks reached it, none of them cycling
 * (FL_SKIN_CAP_PROBE below: 2146 found their cell after 17 more steps on average, 614 gave up
 * on a missing or shaky cell); at 256 no walk reaches the cap and the scans fall 40.6 % ->
 * 26.3 % of the evaluations (docs/skin.md, round 12). */
#define SKIN_WALK_NEAR 8
#define SKIN_WALK_FAR 256

/* The position of key in n records of size bytes, sorted by their ball[4] field at offset
 * off (the stored skin_simplex and the dropped skin_light lists), or SIZE_MAX. */
static size_t key_search(const void *base, size_t n, size_t size, size_t off,
                         const uint32_t key[4])
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        int c = skin_key_cmp((const uint32_t *)((const char *)base + mid * size + off), key);
        if (c == 0) return mid;
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return SIZE_MAX;
}

/* The simplex with balls key (sorted, padded): its index among the stored simplices, or
 * simplex_count + its index among the dropped ones (the mesher's function), or UINT32_MAX when
 * it is in neither list. */
static uint32_t find_simplex(const fl_skin_function *sk, const uint32_t key[4])
{
    size_t b = key[0] < sk->ball_count ? key[0] : sk->ball_count;
    size_t lo = sk->first_stored[b];
    size_t i = key_search(sk->simplex + lo, sk->first_stored[b + 1] - lo, sizeof *sk->simplex,
                          offsetof(skin_simplex, ball), key);
    if (i != SIZE_MAX) return (uint32_t)(lo + i);
    lo = sk->first_dropped[b];
    i = key_search(sk->dropped + lo, sk->first_dropped[b + 1] - lo, sizeof *sk->dropped,
                   offsetof(skin_light, ball), key);
    if (i != SIZE_MAX) return (uint32_t)(sk->simplex_count + lo + i);
#ifdef FL_SKIN_WALK_STATS
    { /* the missing simplices by dimension and sign: positive ball or not */
        extern _Atomic size_t skin_stat_missing[2][4];
        int k = 0, pos = 0;
        while (k < 4 && key[k] != UINT32_MAX)
            pos |= sk->balls[4 * (size_t)key[k++] + 3] > 0;
        if (k) skin_stat_missing[pos][k - 1]++;
    }
#endif
    return UINT32_MAX;
}

/* The key of s without its ball number drop, or with ball add (add != UINT32_MAX). */
static void neighbour_key(const skin_simplex *s, int drop, uint32_t add, uint32_t key[4])
{
    int m = 0;
    for (int i = 0; i <= s->k; i++) {
        if (i == drop) continue;
        if (add != UINT32_MAX && add < s->ball[i] && (m == 0 || key[m - 1] < add)) key[m++] = add;
        key[m++] = s->ball[i];
    }
    if (add != UINT32_MAX && (m == 0 || key[m - 1] < add)) key[m++] = add;
    while (m < 4)
        key[m++] = UINT32_MAX;
}

/* Why a walk gave up (skin_internal.h, SKIN_WHY_*; counted by a FL_SKIN_WALK_STATS build): the
 * neighbour is not listed, the cell is shaky (+ its SKIN_SHAKY_* bits), the power-face box
 * test failed, the step cap was reached, or the walk came back to a cell. */
enum { WHY_MISSING = SKIN_WHY_MISSING, WHY_BOX = SKIN_WHY_BOX, WHY_CAP = SKIN_WHY_CAP,
       WHY_CYCLE = SKIN_WHY_CYCLE, WHY_SHAKY = SKIN_WHY_SHAKY };

#ifdef FL_SKIN_WALK_STATS
#include <stdio.h>
#include <stdlib.h>
static _Atomic size_t stat_eval, stat_walk, stat_dropped, stat_why[16];
/* give-up searches (give_up_search): none found / found; cells tested; the scans' candidates
 * (index list lengths) */
static _Atomic size_t stat_search[2], stat_search_cells, stat_scan_items;
_Atomic size_t skin_stat_missing[2][4];
_Atomic size_t skin_stat_scan_evaluated; /* candidates inside their box (skin_value_scan) */
/* capped walks probed on (FL_SKIN_CAP_PROBE): not ended, found the cell, gave up, cycled */
static _Atomic size_t stat_probe[4], stat_probe_steps[4];
/* restarts of the far walk by where x lies: outside the index, in a cell without list, in a
 * listed cell (then from its seed); [.][1] when that walk answered; the others by why */
static _Atomic size_t stat_restart[3][2], stat_restart_why[3][8];
static void stats_print(void)
{
    size_t e = stat_eval, w = stat_walk;
    fprintf(stderr, "skin walk stats: %zu evaluations, %zu walk answers, %zu scans (%.1f %%):",
            e, w, e - w, e ? 100.0 * (double)(e - w) / (double)e : 0.0);
    fprintf(stderr, " (%zu in dropped cells)", (size_t)stat_dropped);
    static const char *name[16] = {"?", "missing", "box", "cap", "cycle", "", "", "", "shaky?",
                                   "cond", "sliver", "cond+sliver", "degen", "cond+degen",
                                   "sliver+degen", "all3"};
    for (int i = 0; i < 16; i++)
        if (stat_why[i]) fprintf(stderr, " %s %zu", name[i], (size_t)stat_why[i]);
    fprintf(stderr, "; missing simplices (not positive / positive, k = 0..3):");
    for (int p = 0; p < 2; p++)
        for (int k = 0; k < 4; k++)
            fprintf(stderr, " %zu", (size_t)skin_stat_missing[p][k]);
    size_t sr = stat_search[0] + stat_search[1], sc = e - w;
    fprintf(stderr, "; give-up searches: %zu (%zu found the cell; %.1f cells tested each); "
            "%.0f candidates per scan (all scans: %zu evaluated in their box)", sr, (size_t)stat_search[1],
            sr ? (double)stat_search_cells / (double)sr : 0.0,
            sc ? (double)stat_scan_items / (double)sc : 0.0, (size_t)skin_stat_scan_evaluated);
    if (stat_probe[0] + stat_probe[1] + stat_probe[2] + stat_probe[3])
        fprintf(stderr, "; capped walks probed on: %zu unended, %zu ended in a cell (%zu more "
                "steps), %zu gave up, %zu cycled (%zu steps)", (size_t)stat_probe[0],
                (size_t)stat_probe[1], (size_t)stat_probe_steps[1], (size_t)stat_probe[2],
                (size_t)stat_probe[3], (size_t)stat_probe_steps[3]);
    static const char *kind[3] = {"outside", "empty", "listed"};
    fprintf(stderr, "; far walks (answered/not; missing box cap cycle shaky):");
    for (int k = 0; k < 3; k++)
        fprintf(stderr, " %s %zu/%zu (%zu %zu %zu %zu %zu)", kind[k], (size_t)stat_restart[k][1],
                (size_t)stat_restart[k][0], (size_t)stat_restart_why[k][1],
                (size_t)stat_restart_why[k][2], (size_t)stat_restart_why[k][3],
                (size_t)stat_restart_why[k][4], (size_t)stat_restart_why[k][0]);
    fprintf(stderr, "\n");
}
/* FL_SKIN_TRUST: SKIN_SHAKY_* bits the walk ignores (experiments of the counting build) */
static unsigned trust_bits(void)
{
    static _Atomic int init = 0;
    static unsigned bits;
    if (!init) {
        const char *e = getenv("FL_SKIN_TRUST");
        bits = e ? (unsigned)atoi(e) : 0;
        atexit(stats_print);
        init = 1;
    }
    return bits;
}
#define SHAKY(s) ((s)->shaky & SKIN_SHAKY_GIVE_UP & ~trust_bits())
#else
#define SHAKY(s) ((s)->shaky & SKIN_SHAKY_GIVE_UP)
#endif

/* Whether x lies in the mixed cell of simplex id: 1 with *val = G(x); 0 with *next the
 * neighbouring cell across the most violated test; -1 when that neighbour is not listed or the
 * cell is shaky (its tests are not trustworthy; the caller scans), *why then says which. */
static int cell_test(const fl_skin_function *sk, uint32_t id, const double *x, double *val,
                     uint32_t *next, int *why)
{
    const skin_simplex *s = &sk->simplex[id < sk->simplex_count ? id : 0];
    size_t link_lo, link_hi;
    skin_simplex light;
    if (id < sk->simplex_count) {
        link_lo = sk->link_start[id];
        link_hi = sk->link_start[id + 1];
    } else { /* a dropped cell: its frame from the balls, as a stored record would hold it */
        size_t j = id - sk->simplex_count;
        if (skin_simplex_setup(sk->balls, sk->dropped[j].ball, sk->dropped[j].k, &light)) {
            *why = WHY_MISSING;
            return -1;
        }
        light.shaky |= sk->dropped[j].shaky;
        s = &light;
        link_lo = sk->dropped_link_start[j];
        link_hi = sk->dropped_link_start[j + 1];
    }
    double t = sk->t, a[3], e[3][3], f[3], d[3], et[3], mu[4], xi[3] = {0, 0, 0}, sum = 0;
    skin_frame(sk->balls, s, a, e);
    for (int c = 0; c < 3; c++)
        d[c] = x[c] - a[c];
    for (int i = 0; i < s->k; i++)
        et[i] = e[i][0] * d[0] + e[i][1] * d[1] + e[i][2] * d[2];
    for (int i = 0; i < s->k; i++) {
        for (int j = 0; j < s->k; j++)
            xi[i] += s->ginv[i][j] * et[j];
        mu[i + 1] = s->mu_f[i] + (xi[i] - s->mu_f[i]) / (1 - t); /* z* in the frame of s */
        sum += mu[i + 1];
    }
    mu[0] = 1 - sum;
    int worst = -1;
    double wv = -SKIN_WALK_SLACK;
    for (int i = 0; s->k > 0 && i <= s->k; i++)
        if (!(mu[i] >= wv)) { /* NaN counts as violated: never accept it as inside */
            worst = i;
            wv = mu[i] == mu[i] ? mu[i] : -HUGE_VAL;
        }
    if (worst >= 0) {
        uint32_t key[4];
        neighbour_key(s, worst, UINT32_MAX, key);
        *next = find_simplex(sk, key);
        *why = WHY_MISSING;
        return *next == UINT32_MAX ? -1 : 0;
    }
    double proj[3], q[3], ut[3];
    skin_focus(s, a, e, f);
    for (int c = 0; c < 3; c++) {
        proj[c] = a[c];
        for (int i = 0; i < s->k; i++)
            proj[c] += xi[i] * e[i][c];
        q[c] = x[c] - proj[c];
        ut[c] = t * (f[c] - a[c]) + q[c]; /* t (v - a), v = f + q/t in aff nu_X */
    }
    /* v in nu_X: pi_b(v) - pi_X(v) = -2 (v - a).e_b + |e_b|^2 - w_b + w_a >= 0 for every link
     * ball b (e_b = z_b - a), times t so that small t does not amplify q/t */
    const double *b0 = sk->balls + 4 * (size_t)s->ball[0];
    double utl = sqrt(ut[0] * ut[0] + ut[1] * ut[1] + ut[2] * ut[2]), worst_h = 0;
    uint32_t add = UINT32_MAX, add_exact = UINT32_MAX;
    int exact = (s->shaky & SKIN_SHAKY_SLIVER) != 0;
    for (size_t l = link_lo; l < link_hi; l++) {
        const double *b = sk->balls + 4 * (size_t)sk->link[l];
        double eb[3] = {b[0] - b0[0], b[1] - b0[1], b[2] - b0[2]};
        double e2 = eb[0] * eb[0] + eb[1] * eb[1] + eb[2] * eb[2], el = sqrt(e2);
        double h = -2 * (ut[0] * eb[0] + ut[1] * eb[1] + ut[2] * eb[2]) + t * (e2 - b[3] + b0[3]);
        /* rounding of h: a few ulps of its terms' sizes (the weight difference is exact for
         * close weights); not of |w_b| + |w_a|, which for two nearly coincident balls of equal
         * weight (B* has mirror pairs 1e-17 apart) accepted points far outside the thin cell */
        double tol = SKIN_WALK_SLACK * (2 * utl * el + t * (e2 + fabs(b[3] - b0[3])));
        if (!(h >= -tol) && !(h / el >= worst_h)) { /* most violated per unit distance */
            worst_h = h == h ? h / el : -HUGE_VAL;
            add = sk->link[l];
        } else if ((exact || fabs(h) <= tol) && add == UINT32_MAX && add_exact == UINT32_MAX) {
            /* Decided exactly (0: on the facet, accepted): every test h does not reject on a
             * face of a sliver, where h's rounding is not bounded by tol (a skinny X, the link
             * ball nearly in aff X), and every test inside the slack band elsewhere: the slack
             * is a distance only when h grows like |e_b| along aff nu_X, and for a nearly flat,
             * nearly cospherical coface X + b it barely changes there, so |h| <= tol held far
             * outside the cell. On the npm bunny's B* a dropped triangle accepted a point where
             * G = -0.0037 (h = -1e-16, tol 3e-16, exact sign -1); the graded mesher labelled
             * that corner outside and made a bubble (round 15). */
            int sg = skin_link_sign_exact(sk->balls, s, sk->link[l], x, t);
            if (sg == 2) {
                *why = WHY_SHAKY | s->shaky;
                return -1;
            }
            if (sg < 0) add_exact = sk->link[l];
        }
    }
    if (add == UINT32_MAX) add = add_exact;
    if (add != UINT32_MAX) {
        uint32_t key[4];
        neighbour_key(s, -1, add, key);
        *next = find_simplex(sk, key);
        *why = WHY_MISSING;
        /* X + add is not listed: a flat simplex (B*'s focus balls lie in their face's plane or
         * line; skin_simplex_setup rejects it), whose mixed cell is flat too. Step round it to
         * one of its other faces holding add, dropping the vertex of X with the smallest
         * barycentric coordinate of z* that gives a listed face. Only the speed depends on the
         * path (a cell is accepted by its own tests alone), and walk() stops a path that comes
         * back to a cell. Scans 23.1 % -> 7.1 % of the evaluations on cube.off's B* (eps 0.5),
         * 26.3 % -> 6.2 % on sphere.off's (eps 0.3); the first listed face instead of the
         * smallest coordinate: 9.7 % and 10.1 % (docs/skin.md, round 12). */
        int tried = 0;
        while (*next == UINT32_MAX && tried != (1 << (s->k + 1)) - 1) {
            int i = -1; /* the untried vertex of X with the smallest barycentric coordinate */
            for (int j = 0; j <= s->k; j++)
                if (!(tried >> j & 1) && (i < 0 || mu[j] < mu[i])) i = j;
            tried |= 1 << i;
            uint32_t face[4];
            neighbour_key(s, i, add, face);
            *next = find_simplex(sk, face);
        }
        return *next == UINT32_MAX ? -1 : 0;
    }
    if (SHAKY(s)) {
        *why = WHY_SHAKY | SHAKY(s);
        return -1;
    }
    for (int c = 0; s->box_exact == SKIN_BOX_VORONOI && c < 3; c++) { /* t v in t box(nu_X) */
        double tv = ut[c] + t * a[c];
        double pad = SKIN_WALK_SLACK * (fabs(tv) + t * (fabs(s->nu_lo[c]) + fabs(s->nu_hi[c])));
        if (!(tv >= t * s->nu_lo[c] - pad && tv <= t * s->nu_hi[c] + pad)) {
            *why = WHY_BOX;
            return -1;
        }
    }
    *val = skin_combination_value(sk->balls, s, t, a, e, mu, x);
    /* a dropped cell: every ball of X has weight <= 0, so G >= 0 on its whole mixed cell */
    if (id >= sk->simplex_count && !(*val >= 0)) *val = 0;
    return 1;
}

/* Walks from *cur for at most steps cells; 1 with *val when the cell of x was found. A walk
 * that comes back to one of the last SKIN_WALK_SEEN cells it left is going round in circles
 * (the tests of neighbouring cells contradict each other by rounding): it gives up at once.
 * Not a matter of the walk's order: on cube.off's B* (eps 0.5) its cycles run through 3-8
 * vertices, edges and triangles of slivers, and a stochastic walk continued from them (a
 * random violated test each step) ended in a cell in 29 of 2040 cases within 128 steps
 * (round 13, docs/skin.md), so no accepting cell lies along those paths. */
#define SKIN_WALK_SEEN 8
static int walk(const fl_skin_function *sk, const double *x, uint32_t *cur, int steps,
                double *val, int *why)
{
    uint32_t seen[SKIN_WALK_SEEN];
    for (int i = 0; i < steps; i++) {
        uint32_t next = 0;
        int r = cell_test(sk, *cur, x, val, &next, why);
        if (r) return r > 0;
        seen[i % SKIN_WALK_SEEN] = *cur;
        for (int j = 0; j <= i && j < SKIN_WALK_SEEN; j++)
            if (seen[j] == next) {
                *why = WHY_CYCLE;
                return 0;
            }
        *cur = next;
    }
    *why = WHY_CAP;
#ifdef FL_SKIN_WALK_STATS
    /* FL_SKIN_CAP_PROBE=N (counting build): walk on up to N more steps from the capped walk's
     * cell, recording every cell, to tell long walks (they end) from cycles longer than
     * SKIN_WALK_SEEN (a cell comes back) */
    static _Atomic long probe = -1;
    if (probe < 0) {
        const char *e = getenv("FL_SKIN_CAP_PROBE");
        probe = e ? atol(e) : 0;
    }
    if (probe > 0 && steps > SKIN_WALK_NEAR) {
        uint32_t *hist = malloc((size_t)probe * sizeof *hist), c = *cur;
        long n = 0, end = 0;
        double v;
        int w;
        for (; n < probe && hist; n++) {
            uint32_t next = 0;
            int r = cell_test(sk, c, x, &v, &next, &w);
            if (r) {
                end = r > 0 ? 1 : 2;
                break;
            }
            for (long j = 0; j < n && !end; j++)
                end = hist[j] == next ? 3 : 0;
            if (end) break;
            hist[n] = c;
            c = next;
        }
        stat_probe[end]++;
        stat_probe_steps[end] += (size_t)n;
        free(hist);
    }
#endif
    return 0;
}

/* The restart cells of the walk. A walk from the caller's start that does not end within
 * SKIN_WALK_NEAR steps (the previous point was far) restarts from the index cell of x. Each
 * listed index cell keeps the mixed cell holding its centre, found once here by walks from the
 * previous cell's (the cells are visited row by row, so these walks are short), or its first
 * listed simplex where that walk gives up. The seed only changes where walks start: a cell is
 * accepted by its own tests, so values are unchanged beyond rounding. Measured on 20 000 points
 * within a positive ball of the npm bunny's B* (eps 1; 179 200 index cells, 1.5 s to seed):
 * from the first listed simplex 90.4 steps on average and 466 walks over 256 steps, from the
 * seed 13.1 and 28; cube.off's B* 11.8 -> 3.4, sphere.off's 43.1 -> 13.2 (docs/skin.md,
 * round 15). */
fl_status skin_seed_cells(fl_skin_function *sk, fl_error *err)
{
    size_t cells = sk->dims[0] * sk->dims[1] * sk->dims[2];
    sk->cell_seed = fl_alloc_array(cells + 1, sizeof *sk->cell_seed);
    if (!sk->cell_seed) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
    uint32_t prev = UINT32_MAX;
    for (size_t id = 0; id < cells; id++) {
        sk->cell_seed[id] = UINT32_MAX;
        if (sk->cell_start[id] == sk->cell_start[id + 1]) continue;
        uint32_t first = sk->cell_item[sk->cell_start[id]], cur = prev;
        double x[3], val;
        skin_index_centre(sk, id, x);
        int why;
        int ok = cur != UINT32_MAX && walk(sk, x, &cur, SKIN_WALK_FAR, &val, &why);
        if (!ok) {
            cur = first;
            ok = walk(sk, x, &cur, SKIN_WALK_FAR, &val, &why);
        }
        sk->cell_seed[id] = ok ? cur : first;
        if (ok) prev = cur;
    }
    return FL_OK;
}

/* Where the walk gave up (a cycle, the step cap, a neighbour not listed) x often lies in a cell next to the one it stopped in, which its most-violated
 * choice did not lead to. A breadth-first search over the facets and cofaces of that cell
 * collects at most SKIN_SEARCH_CELLS cells and tests each with the walk's own test (cell_test:
 * the same slack, exact sliver tests, shaky cells never accepted), so a cell it accepts is one
 * the walk would have answered in, with the same value. 1 with *cur the cell and *val its
 * value, 0 when none accepts (the caller scans). Cube.off's B* (eps 0.5): 320 of 712 give-ups
 * answered, scans 7.1 % -> 2.4 % of the evaluations; sphere.off's (eps 0.3) 187 of 543, 6.2 %
 * -> 3.6 %; same meshes (docs/skin.md round 13). */
#define SKIN_SEARCH_CELLS 48
static int give_up_search(const fl_skin_function *sk, const double *x, uint32_t *cur,
                          double *val)
{
#ifdef FL_SKIN_WALK_STATS
    if (getenv("FL_SKIN_NO_SEARCH")) return 0; /* the before/after counts */
#endif
    uint32_t q[SKIN_SEARCH_CELLS];
    int n = 1;
    q[0] = *cur;
    for (int h = 0; h < n && n < SKIN_SEARCH_CELLS; h++) {
        skin_simplex s; /* only its key and k are set: all neighbour_key reads */
        const uint32_t *ball;
        size_t lo, hi;
        if (q[h] < sk->simplex_count) {
            ball = sk->simplex[q[h]].ball;
            s.k = sk->simplex[q[h]].k;
            lo = sk->link_start[q[h]];
            hi = sk->link_start[q[h] + 1];
        } else {
            size_t j = q[h] - sk->simplex_count;
            ball = sk->dropped[j].ball;
            s.k = sk->dropped[j].k;
            lo = sk->dropped_link_start[j];
            hi = sk->dropped_link_start[j + 1];
        }
        for (int i = 0; i < 4; i++)
            s.ball[i] = ball[i];
        size_t faces = s.k > 0 ? (size_t)s.k + 1 : 0;
        for (size_t i = 0; i < faces + (hi - lo) && n < SKIN_SEARCH_CELLS; i++) {
            uint32_t key[4];
            if (i < faces)
                neighbour_key(&s, (int)i, UINT32_MAX, key);
            else
                neighbour_key(&s, -1, sk->link[lo + i - faces], key);
            uint32_t id = find_simplex(sk, key);
            int seen = id == UINT32_MAX;
            for (int j = 0; j < n && !seen; j++)
                seen = q[j] == id;
            if (!seen) q[n++] = id;
        }
    }
    for (int h = 1; h < n; h++) { /* q[0] is the cell the walk gave up in */
        uint32_t next;
        int why;
        if (cell_test(sk, q[h], x, val, &next, &why) > 0) {
#ifdef FL_SKIN_WALK_STATS
            if (getenv("FL_SKIN_SEARCH_CHECK")) {
                double sv = skin_value_scan(sk, x), v = *val;
                if ((sv <= 0 || v <= 0) && fabs(sv - v) > 1e-9 * (1 + fabs(sv)))
                    fprintf(stderr, "search: cell %u: %.17g, scan %.17g\n", q[h], v, sv);
            }
            stat_search[1]++;
            stat_search_cells += (size_t)h;
#endif
            *cur = q[h];
            return 1;
        }
    }
#ifdef FL_SKIN_WALK_STATS
    stat_search[0]++;
    stat_search_cells += (size_t)n - 1;
#endif
    return 0;
}

/* The cell found (*start updated to it): a stored simplex's index, or SKIN_NO_CELL with
 * *why = SKIN_WHY_DROPPED for a dropped one (callers read stored records of the cells returned:
 * skin_root.c), *val its quadric. */
static uint32_t found(const fl_skin_function *sk, uint32_t cur, uint32_t *start, int *why)
{
    *start = cur;
    *why = 0; /* a first walk that gave up may have set it */
    if (cur < sk->simplex_count) return cur;
#ifdef FL_SKIN_WALK_STATS
    stat_dropped++;
#endif
    *why = SKIN_WHY_DROPPED;
    return SKIN_NO_CELL;
}

uint32_t skin_locate_why(const fl_skin_function *sk, const double x[3], uint32_t *start,
                         double *val, int *why)
{
    *val = HUGE_VAL;
    *why = -1;
    if (!sk->walkable || sk->simplex_count == 0) {
        *val = skin_value_scan(sk, x);
        return SKIN_NO_CELL;
    }
    if (!(fabs(x[0]) <= 1e150 && fabs(x[1]) <= 1e150 && fabs(x[2]) <= 1e150)) return SKIN_NO_CELL;
    uint32_t cur = *start < sk->simplex_count + sk->dropped_count ? *start : 0;
#ifdef FL_SKIN_WALK_STATS
    (void)trust_bits();
    if (++stat_eval % 1000000 == 0) stats_print(); /* a run stopped early still tells */
    stat_walk++;
#endif
    *why = 0;
    if (walk(sk, x, &cur, SKIN_WALK_NEAR, val, why)) return found(sk, cur, start, why);
    /* a far start: restart next to x from the index (or go on walking outside it) */
    size_t cell = 0;
    int kind = !skin_index_cell(sk, x, &cell)                          ? 0 /* outside */
               : sk->cell_start[cell] == sk->cell_start[cell + 1] ? 1 /* no list */
                                                                  : 2;
    if (kind == 2) cur = sk->cell_seed[cell];
    int far = walk(sk, x, &cur, SKIN_WALK_FAR, val, why);
#ifdef FL_SKIN_WALK_STATS
    stat_restart[kind][far]++;
    if (!far) stat_restart_why[kind][*why >= 8 ? 0 : *why]++;
#endif
    if (far) return found(sk, cur, start, why);
    if (give_up_search(sk, x, &cur, val)) {
        uint32_t r = found(sk, cur, start, why);
        *why |= SKIN_WHY_SEARCHED;
        return r;
    }
#ifdef FL_SKIN_WALK_STATS
    stat_walk--;
    stat_why[*why & 15]++;
    {
        size_t c = 0;
        if (skin_index_cell(sk, x, &c)) stat_scan_items += sk->cell_start[c + 1] - sk->cell_start[c];
    }
#endif
    *val = skin_value_scan(sk, x);
    return SKIN_NO_CELL;
}

uint32_t skin_locate(const fl_skin_function *sk, const double x[3], uint32_t *start, double *val)
{
    int why;
    return skin_locate_why(sk, x, start, val, &why);
}

double skin_value_walk(const fl_skin_function *sk, const double x[3], uint32_t *start)
{
    double val;
    skin_locate(sk, x, start, &val);
    return val;
}

double fl_skin_function_value(const fl_skin_function *skin, const double x[3])
{
    if (!skin->walkable) return skin_value_scan(skin, x);
    uint32_t h = atomic_load_explicit(skin->hint, memory_order_relaxed);
    double v = skin_value_walk(skin, x, &h);
    atomic_store_explicit(skin->hint, h, memory_order_relaxed);
    return v;
}

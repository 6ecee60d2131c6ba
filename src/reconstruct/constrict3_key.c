/* Keys that order removable boundary tetrahedra in 3D constriction, and the heap holding them.
 * Keys are constructions (floating point): they only choose among removable tetrahedra, every
 * topological decision is combinatorial (constrict3.c). */
#include <math.h>
#include <stdlib.h>

#include "reconstruct/constrict3_internal.h"

const int constrict3_face[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

static void sub3(const double *a, const double *b, double *d)
{
    d[0] = a[0] - b[0];
    d[1] = a[1] - b[1];
    d[2] = a[2] - b[2];
}

static void cross3(const double *a, const double *b, double *d)
{
    d[0] = a[1] * b[2] - a[2] * b[1];
    d[1] = a[2] * b[0] - a[0] * b[2];
    d[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* thesis Def. 5.2. The circumsphere's centre is C = c_t + h n̂, with c_t the triangle's
 * circumcentre, n̂ the unit normal towards l and h its signed height; then R² = r² + h² and
 * |γ| = 1 - r/R = 1 - 1/sqrt(1 + (h/r)²), positive exactly when h > 0 (C on l's side, eq. 5.2).
 * h follows from |l - C| = R: with l - a - c_t = u + z n̂, h = (|l - a - c_t|² - r²) / (2z). */
double constrict3_gamma_indicator(const double *a, const double *b, const double *c,
                                  const double *l)
{
    double e1[3], e2[3], n[3], t1[3], t2[3], ct[3], la[3];
    sub3(b, a, e1);
    sub3(c, a, e2);
    cross3(e1, e2, n);
    double nn = dot3(n, n);
    if (!(nn > 0))
        return 1.0; /* a sliver face cannot occur in a Delaunay tetrahedralization; never first */
    cross3(e2, n, t1);
    cross3(n, e1, t2);
    double w1 = dot3(e1, e1), w2 = dot3(e2, e2);
    for (int i = 0; i < 3; i++)
        ct[i] = (w1 * t1[i] + w2 * t2[i]) / (2.0 * nn);
    double r2 = dot3(ct, ct);
    sub3(l, a, la);
    double z = fabs(dot3(la, n)) / sqrt(nn);
    double u[3];
    sub3(la, ct, u);
    double num = dot3(u, u) - r2; /* > 0: l outside the circumcylinder, centre on l's side */
    if (!(z > 0) || !(r2 > 0)) return num > 0 ? 1.0 : -1.0;
    double h = num / (2.0 * z);
    double t = fabs(h) / sqrt(r2);
    if (!isfinite(t) || t > 1e150) return h > 0 ? 1.0 : -1.0;
    /* 1 - 1/sqrt(1+t²) without cancellation for small t */
    double s = sqrt(1.0 + t * t);
    double g = t * t / (s * (1.0 + s));
    return h > 0 ? g : -g;
}

static double face_area(const double *p, const uint32_t *t, int k)
{
    const double *a = p + 3 * (size_t)t[constrict3_face[k][0]];
    const double *b = p + 3 * (size_t)t[constrict3_face[k][1]];
    const double *c = p + 3 * (size_t)t[constrict3_face[k][2]];
    double e1[3], e2[3], n[3];
    sub3(b, a, e1);
    sub3(c, a, e2);
    cross3(e1, e2, n);
    return 0.5 * sqrt(dot3(n, n));
}

/* thesis eq. 4.1 (Boissonnat's minimal area change constriction, §4.3.3) */
double constrict3_area_change(const double *p, const uint32_t *t, unsigned boundary_mask)
{
    double inner = 0, outer = 0;
    for (int k = 0; k < 4; k++) {
        double area = face_area(p, t, k);
        if (boundary_mask & (1u << k))
            outer += area;
        else
            inner += area;
    }
    double total = inner + outer;
    return total > 0 ? (inner - outer) / total : 0.0;
}

static int entry_less(const constrict3_entry *x, const constrict3_entry *y)
{
    return x->key < y->key || (x->key == y->key && x->tet < y->tet);
}

int constrict3_heap_push(constrict3_heap *h, constrict3_entry e)
{
    if (h->count == h->cap) {
        size_t cap = h->cap ? 2 * h->cap : 256;
        constrict3_entry *a = fl_realloc_array(h->a, cap, sizeof *a);
        if (!a) return -1;
        h->a = a;
        h->cap = cap;
    }
    size_t i = h->count++;
    while (i > 0) {
        size_t parent = (i - 1) / 2;
        if (!entry_less(&e, &h->a[parent])) break;
        h->a[i] = h->a[parent];
        i = parent;
    }
    h->a[i] = e;
    return 0;
}

constrict3_entry constrict3_heap_pop(constrict3_heap *h)
{
    constrict3_entry top = h->a[0], last = h->a[--h->count];
    size_t i = 0, n = h->count;
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= n) break;
        if (c + 1 < n && entry_less(&h->a[c + 1], &h->a[c])) c++;
        if (!entry_less(&h->a[c], &last)) break;
        h->a[i] = h->a[c];
        i = c;
    }
    if (n > 0) h->a[i] = last;
    return top;
}

void constrict3_heap_free(constrict3_heap *h)
{
    free(h->a);
    h->a = NULL;
    h->count = h->cap = 0;
}

/*
 * list.c — interval lists: the three boolean merges, clipping, membership.
 *
 * A list is read as its boundary sequence b[0] = v[0].enter, b[1] =
 * v[0].exit, b[2] = v[1].enter, …  The invariant (intervals.h) makes that
 * sequence strictly increasing in t, so after consuming the first k
 * boundaries a point is inside exactly when k is odd.  A merge sweeps both
 * sequences together: at each distinct t it consumes every boundary of either
 * operand at that t, recomputes both inside-states by parity, and emits a
 * boundary only when the combined state changes.  Deciding once per distinct
 * t is what makes touching spans merge and zero-length spans vanish, so the
 * output obeys the same invariant without a clean-up pass.  The emitted
 * boundary is the one of the operand whose state changed (a when both did);
 * for a difference, b's boundaries are emitted with their flip toggled.
 */
#include "intervals.h"

#include <assert.h>
#include <string.h>

enum { OP_UNION, OP_INTERSECTION, OP_DIFFERENCE };

int iv_list_init(iv_list *l, int cap, iv_arena *a)
{
    assert(cap >= 0);
    l->n = 0;
    l->cap = 0;
    l->v = iv_arena_alloc(a, (size_t)(cap > 0 ? cap : 1) * sizeof(iv_span));
    if (!l->v) return -1;
    l->cap = cap;
    return 0;
}

/* Boundary k of l in sweep order (0 <= k < 2n). */
static inline const iv_bound *bound_at(const iv_list *l, int k)
{
    const iv_span *s = &l->v[k >> 1];
    return (k & 1) ? &s->exit : &s->enter;
}

static inline int combine(int op, int ina, int inb)
{
    switch (op) {
    case OP_UNION:
        return ina | inb;
    case OP_INTERSECTION:
        return ina & inb;
    default:
        return ina & !inb;
    }
}

/* The one merge; `op` is a constant at each call site, so the compiler folds
 * `combine` into three specialised loops. */
static inline void merge(int op, const iv_list *a, const iv_list *b, iv_list *out)
{
    assert(out != a && out != b);
    assert(out->cap >= a->n + b->n);
    const int na = 2 * a->n, nb = 2 * b->n;
    int i = 0, j = 0, state = 0, n = 0;
    iv_span *o = out->v;
    while (i < na || j < nb) {
        /* A missing operand sorts after everything, including +INFINITY,
         * which is why the comparisons test the index first. */
        double t;
        if (j >= nb || (i < na && bound_at(a, i)->t <= bound_at(b, j)->t))
            t = bound_at(a, i)->t;
        else
            t = bound_at(b, j)->t;
        const int i0 = i, j0 = j;
        while (i < na && bound_at(a, i)->t == t)
            i++;
        while (j < nb && bound_at(b, j)->t == t)
            j++;
        const int ina = i & 1, inb = j & 1;
        const int now = combine(op, ina, inb);
        if (now == state) continue;
        /* The parity of the operand moved iff it consumed an odd count. */
        iv_bound e;
        if ((i - i0) & 1) {
            e = *bound_at(a, i - 1);
        } else {
            assert((j - j0) & 1);
            e = *bound_at(b, j - 1);
            if (op == OP_DIFFERENCE) e.flip ^= 1;
        }
        if (now)
            o[n].enter = e;
        else
            o[n++].exit = e;
        state = now;
    }
    assert(state == 0); /* every list ends outside, at worst at +INFINITY */
    out->n = n;
}

void iv_list_union(const iv_list *a, const iv_list *b, iv_list *out)
{
    if (a->n == 0 || b->n == 0) {
        const iv_list *src = a->n ? a : b;
        assert(out->cap >= src->n);
        memcpy(out->v, src->v, (size_t)src->n * sizeof(iv_span));
        out->n = src->n;
        return;
    }
    merge(OP_UNION, a, b, out);
}

void iv_list_intersection(const iv_list *a, const iv_list *b, iv_list *out)
{
    if (a->n == 0 || b->n == 0) {
        out->n = 0;
        return;
    }
    merge(OP_INTERSECTION, a, b, out);
}

void iv_list_difference(const iv_list *a, const iv_list *b, iv_list *out)
{
    if (a->n == 0 || b->n == 0) {
        assert(out->cap >= a->n);
        memcpy(out->v, a->v, (size_t)a->n * sizeof(iv_span));
        out->n = a->n;
        return;
    }
    merge(OP_DIFFERENCE, a, b, out);
}

void iv_list_clip(iv_list *l, double tmin, double tmax)
{
    /* Spans that only touch the window (exit == tmin or enter == tmax) would
     * become zero-length, so they go too; an empty or NaN window (every
     * comparison false) keeps nothing. */
    int n = 0;
    for (int k = 0; k < l->n; k++) {
        iv_span s = l->v[k];
        if (!(s.exit.t > tmin) || !(s.enter.t < tmax)) continue;
        if (s.enter.t < tmin) s.enter = (iv_bound){tmin, IV_PRIM_NONE, 0, 0};
        if (s.exit.t > tmax) s.exit = (iv_bound){tmax, IV_PRIM_NONE, 0, 0};
        if (!(s.enter.t < s.exit.t)) /* tmin >= tmax */
            continue;
        l->v[n++] = s;
    }
    l->n = n;
}

int iv_list_contains(const iv_list *l, double t)
{
    /* Binary search for the first span whose exit is >= t. */
    int lo = 0, hi = l->n;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (l->v[mid].exit.t < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < l->n && l->v[lo].enter.t <= t;
}

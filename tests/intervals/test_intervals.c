/*
 * test_intervals.c — arena, interval-list merges, and ray–shape intersection,
 * checked against hand-computed values and against an independent
 * point-membership classifier.
 */
#include "../support.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "../../src/intervals/intervals.h"

/* ---- helpers ------------------------------------------------------------ */

/* A list from boundary values: ts[0..2n) enter/exit pairs; prim of
 * boundary k is base + k, part k. */
static iv_list mk(const double *ts, int n, int base)
{
    iv_list l;
    cr_assert_eq(iv_list_init(&l, n + 4, arena), 0);
    for (int i = 0; i < n; i++) {
        l.v[i].enter = (iv_bound){ts[2 * i], base + 2 * i, (uint16_t)(2 * i), 0};
        l.v[i].exit = (iv_bound){ts[2 * i + 1], base + 2 * i + 1, (uint16_t)(2 * i + 1), 0};
    }
    l.n = n;
    return l;
}

static void check_invariant(const iv_list *l, const char *ctx)
{
    for (int i = 0; i < l->n; i++) {
        cr_assert(!isnan(l->v[i].enter.t) && !isnan(l->v[i].exit.t), "%s: NaN", ctx);
        cr_assert(l->v[i].enter.t < l->v[i].exit.t, "%s: span %d empty", ctx, i);
        if (i > 0)
            cr_assert(l->v[i - 1].exit.t < l->v[i].enter.t, "%s: spans %d,%d touch", ctx, i - 1, i);
    }
}

/* ---- arena -------------------------------------------------------------- */

TestSuite(iv_arena, .init = arena_setup, .fini = arena_teardown);

Test(iv_arena, alloc_is_aligned_and_distinct)
{
    char *prev = NULL;
    for (int i = 0; i < 1000; i++) {
        char *p = iv_arena_alloc(arena, (size_t)(i % 37));
        cr_assert_not_null(p);
        cr_assert_eq((uintptr_t)p % 16, 0);
        cr_assert_neq(p, prev);
        memset(p, 0xab, (size_t)(i % 37));
        prev = p;
    }
}

Test(iv_arena, reset_reuses_memory)
{
    void *a = iv_arena_alloc(arena, 100);
    void *b = iv_arena_alloc(arena, 1 << 20); /* forces a new chunk */
    cr_assert(a && b);
    iv_arena_reset(arena);
    cr_assert_eq(iv_arena_alloc(arena, 100), a);
    cr_assert_eq(iv_arena_alloc(arena, 1 << 20), b);
}

Test(iv_arena, steady_state_makes_no_new_chunk)
{
    for (int i = 0; i < 50; i++)
        cr_assert_not_null(iv_arena_alloc(arena, 1000 + 997 * (size_t)i));
    /* With a limit of one byte no chunk can be added: only reuse works. */
    iv_arena_set_limit(arena, 1);
    for (int round = 0; round < 3; round++) {
        iv_arena_reset(arena);
        for (int i = 0; i < 50; i++)
            cr_assert_not_null(iv_arena_alloc(arena, 1000 + 997 * (size_t)i), "round %d", round);
    }
    cr_assert_null(iv_arena_alloc(arena, 100u << 20));
}

Test(iv_arena, limit_refuses)
{
    iv_arena *a = iv_arena_new(1024);
    iv_arena_set_limit(a, 4096);
    cr_assert_not_null(iv_arena_alloc(a, 1000));
    cr_assert_null(iv_arena_alloc(a, 8192));
    cr_assert_not_null(iv_arena_alloc(a, 1000));
    iv_arena_free(a);
}

/* ---- merges by hand ----------------------------------------------------- */

TestSuite(iv_list, .init = arena_setup, .fini = arena_teardown);

Test(iv_list, union_merges_overlap_and_touching)
{
    double ta[] = {0, 2, 5, 6};
    double tb[] = {1, 3, 6, 7, 9, 10};
    iv_list a = mk(ta, 2, 0), b = mk(tb, 3, 100), o;
    iv_list_init(&o, 5, arena);
    iv_list_union(&a, &b, &o);
    cr_assert_eq(o.n, 3);
    cr_assert_eq(o.v[0].enter.t, 0);
    cr_assert_eq(o.v[0].enter.prim, 0);
    cr_assert_eq(o.v[0].exit.t, 3);
    cr_assert_eq(o.v[0].exit.prim, 101);
    /* [5,6] and [6,7] touch: one span [5,7]. */
    cr_assert_eq(o.v[1].enter.t, 5);
    cr_assert_eq(o.v[1].exit.t, 7);
    cr_assert_eq(o.v[1].exit.prim, 103);
    cr_assert_eq(o.v[2].enter.prim, 104);
    check_invariant(&o, "union");
}

Test(iv_list, intersection_drops_zero_length)
{
    double ta[] = {0, 2, 5, 8};
    double tb[] = {2, 6}; /* touches a's first span at 2 only */
    iv_list a = mk(ta, 2, 0), b = mk(tb, 1, 100), o;
    iv_list_init(&o, 3, arena);
    iv_list_intersection(&a, &b, &o);
    cr_assert_eq(o.n, 1);
    cr_assert_eq(o.v[0].enter.t, 5);
    cr_assert_eq(o.v[0].enter.prim, 2);
    cr_assert_eq(o.v[0].exit.t, 6);
    cr_assert_eq(o.v[0].exit.prim, 101);
}

Test(iv_list, intersection_prefers_a_at_equal_t)
{
    double ta[] = {1, 4};
    double tb[] = {1, 4};
    iv_list a = mk(ta, 1, 0), b = mk(tb, 1, 100), o;
    iv_list_init(&o, 2, arena);
    iv_list_intersection(&a, &b, &o);
    cr_assert_eq(o.n, 1);
    cr_assert_eq(o.v[0].enter.prim, 0);
    cr_assert_eq(o.v[0].exit.prim, 1);
}

Test(iv_list, difference_flips_b_and_splits)
{
    double ta[] = {0, 10};
    double tb[] = {2, 3, 5, 12};
    iv_list a = mk(ta, 1, 0), b = mk(tb, 2, 100), o;
    iv_list_init(&o, 3, arena);
    iv_list_difference(&a, &b, &o);
    cr_assert_eq(o.n, 2);
    cr_assert_eq(o.v[0].enter.prim, 0);
    cr_assert_eq(o.v[0].enter.flip, 0);
    cr_assert_eq(o.v[0].exit.t, 2);
    cr_assert_eq(o.v[0].exit.prim, 100);
    cr_assert_eq(o.v[0].exit.flip, 1);
    cr_assert_eq(o.v[1].enter.t, 3);
    cr_assert_eq(o.v[1].enter.prim, 101);
    cr_assert_eq(o.v[1].enter.flip, 1);
    cr_assert_eq(o.v[1].exit.t, 5);
    cr_assert_eq(o.v[1].exit.flip, 1);
}

Test(iv_list, difference_flip_toggles_twice)
{
    double ta[] = {0, 10}, tb[] = {2, 3};
    iv_list a = mk(ta, 1, 0), b = mk(tb, 1, 100), o;
    b.v[0].exit.flip = 1; /* already flipped by an inner difference */
    iv_list_init(&o, 3, arena);
    iv_list_difference(&a, &b, &o);
    cr_assert_eq(o.v[1].enter.prim, 101);
    cr_assert_eq(o.v[1].enter.flip, 0);
}

Test(iv_list, difference_to_nothing)
{
    double ta[] = {1, 2}, tb[] = {0, 3};
    iv_list a = mk(ta, 1, 0), b = mk(tb, 1, 100), o;
    iv_list_init(&o, 2, arena);
    iv_list_difference(&a, &b, &o);
    cr_assert_eq(o.n, 0);
}

Test(iv_list, infinite_ends)
{
    double ta[] = {-INFINITY, 3}, tb[] = {1, INFINITY};
    iv_list a = mk(ta, 1, 0), b = mk(tb, 1, 100), o;
    iv_list_init(&o, 2, arena);
    iv_list_union(&a, &b, &o);
    cr_assert_eq(o.n, 1);
    cr_assert(isinf(o.v[0].enter.t) && o.v[0].enter.t < 0);
    cr_assert(isinf(o.v[0].exit.t) && o.v[0].exit.t > 0);
    iv_list_intersection(&a, &b, &o);
    cr_assert_eq(o.n, 1);
    cr_assert_eq(o.v[0].enter.t, 1);
    cr_assert_eq(o.v[0].exit.t, 3);
    iv_list_difference(&a, &b, &o);
    cr_assert_eq(o.n, 1);
    cr_assert(isinf(o.v[0].enter.t));
    cr_assert_eq(o.v[0].exit.t, 1);
    cr_assert_eq(o.v[0].exit.flip, 1);
}

Test(iv_list, empty_operands)
{
    double ta[] = {1, 2};
    iv_list a = mk(ta, 1, 0), e = mk(NULL, 0, 0), o;
    iv_list_init(&o, 2, arena);
    iv_list_union(&e, &a, &o);
    cr_assert_eq(o.n, 1);
    iv_list_intersection(&a, &e, &o);
    cr_assert_eq(o.n, 0);
    iv_list_difference(&a, &e, &o);
    cr_assert_eq(o.n, 1);
    iv_list_difference(&e, &a, &o);
    cr_assert_eq(o.n, 0);
}

Test(iv_list, clip_marks_cuts)
{
    double ts[] = {-INFINITY, 1, 2, 3, 4, 6, 7, 9};
    iv_list l = mk(ts, 4, 0);
    iv_list_clip(&l, 1, 5);
    /* [-inf,1] touches the window: gone.  [2,3] kept.  [4,6] cut at 5. */
    cr_assert_eq(l.n, 2);
    cr_assert_eq(l.v[0].enter.t, 2);
    cr_assert_eq(l.v[0].enter.prim, 2);
    cr_assert_eq(l.v[1].exit.t, 5);
    cr_assert_eq(l.v[1].exit.prim, IV_PRIM_NONE);
    cr_assert_eq(l.v[1].exit.part, 0);
    cr_assert_eq(l.v[1].exit.flip, 0);
    iv_list_clip(&l, 2.5, 2.5);
    cr_assert_eq(l.n, 0);
}

Test(iv_list, clip_cuts_infinite)
{
    double ts[] = {-INFINITY, INFINITY};
    iv_list l = mk(ts, 1, 0);
    iv_list_clip(&l, 0, 10);
    cr_assert_eq(l.n, 1);
    cr_assert_eq(l.v[0].enter.t, 0);
    cr_assert_eq(l.v[0].enter.prim, IV_PRIM_NONE);
    cr_assert_eq(l.v[0].exit.t, 10);
}

Test(iv_list, contains_closed_ends)
{
    double ts[] = {1, 2, 4, 8};
    iv_list l = mk(ts, 2, 0);
    cr_assert(!iv_list_contains(&l, 0.5));
    cr_assert(iv_list_contains(&l, 1));
    cr_assert(iv_list_contains(&l, 2));
    cr_assert(!iv_list_contains(&l, 3));
    cr_assert(iv_list_contains(&l, 4));
    cr_assert(iv_list_contains(&l, 7.9));
    cr_assert(!iv_list_contains(&l, 8.1));
    iv_list e = mk(NULL, 0, 0);
    cr_assert(!iv_list_contains(&e, 1));
}

/* ---- merges: property test ------------------------------------------------ */

/* A random list on an integer grid (so that equal t between operands and
 * touching spans are common), sometimes with infinite ends. */
static iv_list random_list(int base)
{
    int n = rng_int(5);
    double ts[10] = {0};
    int g = -10 + rng_int(3);
    for (int i = 0; i < 2 * n; i++) {
        g += 1 + rng_int(3);
        ts[i] = g;
    }
    if (n > 0 && rng_int(4) == 0) ts[0] = -INFINITY;
    if (n > 0 && rng_int(4) == 0) ts[2 * n - 1] = INFINITY;
    iv_list l = mk(ts, n, base);
    for (int i = 0; i < n; i++) {
        l.v[i].enter.flip = (uint16_t)rng_int(2);
        l.v[i].exit.flip = (uint16_t)rng_int(2);
    }
    return l;
}

/* Where boundary b came from: it must be a copy of one of the inputs'
 * boundaries at the same t (flip toggled for b's in a difference). */
static int provenance_ok(const iv_bound *e, const iv_list *a, const iv_list *b, int diff)
{
    for (int i = 0; i < a->n; i++) {
        const iv_bound *x[2] = {&a->v[i].enter, &a->v[i].exit};
        for (int k = 0; k < 2; k++)
            if (x[k]->prim == e->prim)
                return x[k]->t == e->t && x[k]->part == e->part && x[k]->flip == e->flip;
    }
    for (int i = 0; i < b->n; i++) {
        const iv_bound *x[2] = {&b->v[i].enter, &b->v[i].exit};
        for (int k = 0; k < 2; k++)
            if (x[k]->prim == e->prim)
                return x[k]->t == e->t && x[k]->part == e->part &&
                       x[k]->flip == (e->flip ^ (diff ? 1 : 0));
    }
    return 0;
}

Test(iv_list, merges_match_pointwise_truth)
{
    const uint64_t seed = 0x1e55ed;
    rng_seed(seed);
    for (int it = 0; it < 20000; it++) {
        iv_arena_reset(arena);
        iv_list a = random_list(0), b = random_list(100), o;
        iv_list_init(&o, a.n + b.n, arena);
        int op = rng_int(3);
        if (op == 0)
            iv_list_union(&a, &b, &o);
        else if (op == 1)
            iv_list_intersection(&a, &b, &o);
        else
            iv_list_difference(&a, &b, &o);
        check_invariant(&o, "merge");
        for (int i = 0; i < o.n; i++) {
            cr_assert(provenance_ok(&o.v[i].enter, &a, &b, op == 2),
                      "seed %#llx iter %d op %d: enter %d has no source", (unsigned long long)seed,
                      it, op, i);
            cr_assert(provenance_ok(&o.v[i].exit, &a, &b, op == 2),
                      "seed %#llx iter %d op %d: exit %d has no source", (unsigned long long)seed,
                      it, op, i);
        }
        /* Off-grid samples are never within 1e-7 of a boundary. */
        for (int s = 0; s < 40; s++) {
            double t = -12.5 + s + rng_uniform(0.01, 0.99) * (s % 2);
            int ia = iv_list_contains(&a, t), ib = iv_list_contains(&b, t);
            int want = op == 0 ? (ia || ib) : op == 1 ? (ia && ib) : (ia && !ib);
            cr_assert_eq(iv_list_contains(&o, t), want,
                         "seed %#llx iter %d op %d t %g: got %d want %d", (unsigned long long)seed,
                         it, op, t, !want, want);
        }
        /* Clip against the same truth. */
        double c0 = rng_int(20) - 10 + 0.5, c1 = c0 + rng_int(10) + 0.25;
        iv_list_clip(&o, c0, c1);
        check_invariant(&o, "clip");
        for (int s = 0; s < 30; s++) {
            double t = -15.3 + s;
            int ia = iv_list_contains(&a, t), ib = iv_list_contains(&b, t);
            int want = (op == 0   ? (ia || ib)
                        : op == 1 ? (ia && ib)
                                  : (ia && !ib)) &&
                       t >= c0 && t <= c1;
            cr_assert_eq(iv_list_contains(&o, t), want, "seed %#llx iter %d clip t %g",
                         (unsigned long long)seed, it, t);
        }
    }
}

/* ---- shapes by hand -------------------------------------------------------- */

TestSuite(iv_shape, .init = arena_setup, .fini = arena_teardown);

/* Intersect and return the span count; the span goes to *sp. */
static int hit(iv_shape s, double ox, double oy, double oz, double dx, double dy, double dz,
               iv_span *sp)
{
    iv_list l;
    cr_assert_eq(iv_list_init(&l, 1, arena), 0);
    double o[3] = {ox, oy, oz}, d[3] = {dx, dy, dz};
    int r = iv_shape_intersect(&s, o, d, 7, &l);
    cr_assert(r == 0 || r == 1);
    cr_assert_eq(l.n, r);
    if (r) {
        cr_assert(!isnan(l.v[0].enter.t) && !isnan(l.v[0].exit.t));
        cr_assert(l.v[0].enter.t < l.v[0].exit.t);
        cr_assert_eq(l.v[0].enter.prim, 7);
        *sp = l.v[0];
    }
    return r;
}

Test(iv_shape, sphere_known_hits)
{
    iv_span s;
    cr_assert_eq(hit(sphere(2), -5, 0, 0, 1, 0, 0, &s), 1);
    near(s.enter.t, 3, 1e-14);
    near(s.exit.t, 7, 1e-14);
    /* Unnormalised direction: t scales. */
    cr_assert_eq(hit(sphere(2), -5, 0, 0, 2, 0, 0, &s), 1);
    near(s.enter.t, 1.5, 1e-14);
    near(s.exit.t, 3.5, 1e-14);
    /* Starting inside: the enter is behind the origin. */
    cr_assert_eq(hit(sphere(2), 0, 0, 0, 0, 0, -1, &s), 1);
    near(s.enter.t, -2, 1e-14);
    near(s.exit.t, 2, 1e-14);
    /* Off-centre chord: y = 1 gives half-chord sqrt(3). */
    cr_assert_eq(hit(sphere(2), -5, 1, 0, 1, 0, 0, &s), 1);
    near(s.enter.t, 5 - sqrt(3), 1e-14);
    near(s.exit.t, 5 + sqrt(3), 1e-14);
    cr_assert_eq(s.enter.part, IV_PART_SURFACE);
}

Test(iv_shape, sphere_tangent_and_miss)
{
    iv_span s;
    cr_assert_eq(hit(sphere(2), -5, 2, 0, 1, 0, 0, &s), 0);
    cr_assert_eq(hit(sphere(2), -5, 2.0001, 0, 1, 0, 0, &s), 0);
    cr_assert_eq(hit(sphere(2), -5, 1.9999, 0, 1, 0, 0, &s), 1);
    cr_assert_eq(hit(sphere(0), 0, 0, 0, 1, 0, 0, &s), 0);
    cr_assert_eq(hit(sphere(-1), 0, 0, 0, 1, 0, 0, &s), 0);
}

Test(iv_shape, sphere_small_and_far_is_accurate)
{
    /* B² - AC would cancel ~1e12 against ~1e12 here, leaving noise. */
    iv_span s;
    cr_assert_eq(hit(sphere(1e-3), -1e6, 0, 0, 1, 0, 0, &s), 1);
    near(s.enter.t, 1e6 - 1e-3, 1e-9);
    near(s.exit.t, 1e6 + 1e-3, 1e-9);
    cr_assert_eq(hit(sphere(1e-3), -1e6, 5e-4, 0, 1, 0, 0, &s), 1);
    near(s.exit.t - s.enter.t, 2 * sqrt(1e-6 - 25e-8), 1e-9);
}

Test(iv_shape, box_known_hits)
{
    iv_span s;
    iv_shape b = box(0, 0, 0, 1, 2, 3);
    cr_assert_eq(hit(b, -5, 0.5, 0.5, 1, 0, 0, &s), 1);
    near(s.enter.t, 5, 0);
    near(s.exit.t, 6, 0);
    cr_assert_eq(s.enter.part, IV_PART_BOX_XMIN);
    cr_assert_eq(s.exit.part, IV_PART_BOX_XMAX);
    cr_assert_eq(hit(b, 0.5, 0.5, 10, 0, 0, -2, &s), 1);
    near(s.enter.t, 3.5, 0);
    near(s.exit.t, 5, 0);
    cr_assert_eq(s.enter.part, IV_PART_BOX_ZMAX);
    cr_assert_eq(s.exit.part, IV_PART_BOX_ZMIN);
    /* Diagonal: x in [0,1] for t in [1,2], y in [0,2] for t in [1.5,3.5]. */
    cr_assert_eq(hit(b, -1, -1.5, 1, 1, 1, 0, &s), 1);
    near(s.enter.t, 1.5, 0);
    cr_assert_eq(s.enter.part, IV_PART_BOX_YMIN);
    near(s.exit.t, 2, 0);
    cr_assert_eq(s.exit.part, IV_PART_BOX_XMAX);
    /* Only touching an edge: zero length, no span. */
    cr_assert_eq(hit(b, -1, -2, 1, 1, 1, 0, &s), 0);
}

Test(iv_shape, box_parallel_slabs)
{
    iv_span s;
    iv_shape b = box(0, 0, 0, 1, 1, 1);
    /* Parallel to y and z slabs and inside them: only x bounds the span. */
    cr_assert_eq(hit(b, 3, 0.5, 0.5, -1, 0, 0, &s), 1);
    near(s.enter.t, 2, 0);
    near(s.exit.t, 3, 0);
    /* Parallel and outside: miss, whatever the other axes say. */
    cr_assert_eq(hit(b, 3, 1.5, 0.5, -1, 0, 0, &s), 0);
    cr_assert_eq(hit(b, 3, 0.5, -0.5, -1, 0, 0, &s), 0);
    /* In a face's plane counts as inside (closed box). */
    cr_assert_eq(hit(b, 3, 1, 0.5, -1, 0, 0, &s), 1);
    /* Zero direction inside: the whole line; outside: nothing. */
    cr_assert_eq(hit(b, 0.5, 0.5, 0.5, 0, 0, 0, &s), 1);
    cr_assert(isinf(s.enter.t) && s.enter.t < 0 && isinf(s.exit.t) && s.exit.t > 0);
    cr_assert_eq(hit(b, 1.5, 0.5, 0.5, 0, 0, 0, &s), 0);
    /* Negative zero is zero. */
    cr_assert_eq(hit(b, 3, 0.5, 0.5, -1, -0.0, 0, &s), 1);
}

Test(iv_shape, box_subnormal_direction_is_not_nan)
{
    iv_span s;
    iv_shape b = box(0, 0, 0, 1, 1, 1);
    /* o on the y = 0 plane with a subnormal dy: 1/dy = inf, 0·inf = NaN
     * would poison a multiply-by-reciprocal slab test. */
    double tiny = 4.9406564584124654e-324;
    cr_assert_eq(hit(b, -1, 0, 0.5, 1, tiny, 0, &s), 1);
    near(s.enter.t, 1, 0);
    near(s.exit.t, 2, 0);
    /* From the y = 1 plane going down, and from y = 0 going down (out). */
    cr_assert_eq(hit(b, -1, 1, 0.5, 1, -tiny, 0, &s), 1);
    near(s.enter.t, 1, 0);
    near(s.exit.t, 2, 0);
    cr_assert_eq(hit(b, -1, 0, 0.5, 1, -tiny, 0, &s), 0);
}

Test(iv_shape, halfspace_hits)
{
    iv_span s;
    iv_shape h = halfspace(0, 0, 2, 2); /* z <= 1 */
    cr_assert_eq(hit(h, 0, 0, 5, 0, 0, -1, &s), 1);
    near(s.enter.t, 4, 0);
    cr_assert(isinf(s.exit.t) && s.exit.t > 0);
    cr_assert_eq(hit(h, 0, 0, 5, 0, 0, 1, &s), 1);
    cr_assert(isinf(s.enter.t) && s.enter.t < 0);
    near(s.exit.t, -4, 0);
    cr_assert_eq(hit(h, 0, 0, 0, 1, 0, 0, &s), 1);
    cr_assert(isinf(s.enter.t) && isinf(s.exit.t));
    cr_assert_eq(hit(h, 0, 0, 5, 1, 0, 0, &s), 0);
    /* Tiny slope: -c/a overflows to -inf, the span is the whole line. */
    cr_assert_eq(hit(h, 0, 0, 0, 1, 0, 1e-320, &s), 1);
}

Test(iv_shape, cylinder_hits)
{
    iv_span s;
    iv_shape c = cone(1, 1, 2);
    cr_assert_eq(hit(c, -5, 0, 1, 1, 0, 0, &s), 1);
    near(s.enter.t, 4, 1e-14);
    near(s.exit.t, 6, 1e-14);
    cr_assert_eq(s.enter.part, IV_PART_CONE_SIDE);
    cr_assert_eq(s.exit.part, IV_PART_CONE_SIDE);
    /* Along the axis, both directions. */
    cr_assert_eq(hit(c, 0, 0, -3, 0, 0, 1, &s), 1);
    near(s.enter.t, 3, 0);
    near(s.exit.t, 5, 0);
    cr_assert_eq(s.enter.part, IV_PART_CONE_BOTTOM);
    cr_assert_eq(s.exit.part, IV_PART_CONE_TOP);
    cr_assert_eq(hit(c, 0.5, 0, 5, 0, 0, -1, &s), 1);
    near(s.enter.t, 3, 0);
    near(s.exit.t, 5, 0);
    cr_assert_eq(s.enter.part, IV_PART_CONE_TOP);
    cr_assert_eq(s.exit.part, IV_PART_CONE_BOTTOM);
    /* Parallel to the axis outside the radius: miss. */
    cr_assert_eq(hit(c, 1.5, 0, 5, 0, 0, -1, &s), 0);
    /* Parallel to the caps: in the top plane counts, above it misses. */
    cr_assert_eq(hit(c, -5, 0, 2, 1, 0, 0, &s), 1);
    cr_assert_eq(hit(c, -5, 0, 2.001, 1, 0, 0, &s), 0);
    /* Tangent to the side. */
    cr_assert_eq(hit(c, -5, 1, 1, 1, 0, 0, &s), 0);
    /* Along a line of the side: grazing. */
    cr_assert_eq(hit(c, 1, 0, 5, 0, 0, -1, &s), 0);
    /* Through a cap and the side: from (0,0,3) towards (2,0,-1)·t. */
    cr_assert_eq(hit(c, 0, 0, 3, 1, 0, -1, &s), 0); /* touches the rim only */
    cr_assert_eq(hit(c, 0, 0, 3, 0.5, 0, -1, &s), 1);
    near(s.enter.t, 1, 1e-14);
    cr_assert_eq(s.enter.part, IV_PART_CONE_TOP);
    near(s.exit.t, 2, 1e-14); /* x = 1 at z = 1 */
    cr_assert_eq(s.exit.part, IV_PART_CONE_SIDE);
}

Test(iv_shape, cone_frustum_hits)
{
    iv_span s;
    iv_shape c = cone(1, 2, 1); /* r(z) = 1 + z */
    cr_assert_eq(hit(c, -5, 0, 0.5, 1, 0, 0, &s), 1);
    near(s.enter.t, 3.5, 1e-14);
    near(s.exit.t, 6.5, 1e-14);
    /* Starting inside, going down through the bottom. */
    cr_assert_eq(hit(c, 0, 0, 0.5, 0, 0, -1, &s), 1);
    near(s.enter.t, -0.5, 0);
    near(s.exit.t, 0.5, 0);
}

Test(iv_shape, cone_apex_hits)
{
    iv_span s;
    iv_shape c = cone(2, 0, 2); /* r(z) = 2 - z, apex (0,0,2) */
    cr_assert_eq(hit(c, -5, 0, 1, 1, 0, 0, &s), 1);
    near(s.enter.t, 4, 1e-14);
    near(s.exit.t, 6, 1e-14);
    /* Along the axis to the apex and back. */
    cr_assert_eq(hit(c, 0, 0, -3, 0, 0, 1, &s), 1);
    near(s.enter.t, 3, 0);
    near(s.exit.t, 5, 0);
    cr_assert_eq(s.enter.part, IV_PART_CONE_BOTTOM);
    cr_assert_eq(hit(c, 0, 0, 7, 0, 0, -2, &s), 1);
    near(s.enter.t, 2.5, 0);
    near(s.exit.t, 3.5, 0);
    /* Horizontal through the apex: a single point, no span; just below it a
     * short chord. */
    cr_assert_eq(hit(c, -5, 0, 2, 1, 0, 0, &s), 0);
    cr_assert_eq(hit(c, -5, 0, 1.999, 1, 0, 0, &s), 1);
    near(s.exit.t - s.enter.t, 0.002, 1e-12);
    /* Parallel to a generator (the quadratic degenerates to linear):
     * x = -2 + t, z = 3 - t is inside for t in [1.5, 3]. */
    cr_assert_eq(hit(c, -2, 0, 3, 1, 0, -1, &s), 1);
    near(s.enter.t, 1.5, 1e-14);
    near(s.exit.t, 3, 1e-14);
    cr_assert_eq(s.enter.part, IV_PART_CONE_SIDE);
    cr_assert_eq(s.exit.part, IV_PART_CONE_BOTTOM);
    /* The same line but on the surface of the double cone: grazing. */
    cr_assert_eq(hit(c, -1, 0, 3, 1, 0, -1, &s), 0);
    /* Steeper than the cone, missing the apex by a little: the phantom
     * nappe above the apex must not count. */
    cr_assert_eq(hit(c, 0.01, 0, 5, 0, 0, -1, &s), 1);
    near(s.enter.t, 3.01, 1e-12);
    near(s.exit.t, 5, 1e-12);
    /* Apex at the bottom. */
    iv_shape v = cone(0, 1, 1);
    cr_assert_eq(hit(v, 0, 0, 5, 0, 0, -1, &s), 1);
    near(s.enter.t, 4, 0);
    near(s.exit.t, 5, 0);
    cr_assert_eq(hit(v, -3, 0, 0.5, 1, 0, 0, &s), 1);
    near(s.enter.t, 2.5, 1e-14);
    near(s.exit.t, 3.5, 1e-14);
    cr_assert_eq(hit(cone(0, 0, 1), 0, 0, 0.5, 0, 0, 1, &s), 0);
}

Test(iv_shape, normals)
{
    double n[3];
    iv_shape sp = sphere(2);
    iv_shape_normal(&sp, (double[3]){0, 2, 0}, IV_PART_SURFACE, n);
    near(n[1], 1, 1e-15);
    iv_shape b = box(0, 0, 0, 1, 1, 1);
    int parts[6] = {IV_PART_BOX_XMIN, IV_PART_BOX_XMAX, IV_PART_BOX_YMIN,
                    IV_PART_BOX_YMAX, IV_PART_BOX_ZMIN, IV_PART_BOX_ZMAX};
    for (int i = 0; i < 6; i++) {
        iv_shape_normal(&b, (double[3]){0.5, 0.5, 0.5}, parts[i], n);
        for (int k = 0; k < 3; k++)
            near(n[k], k == i / 2 ? (i % 2 ? 1 : -1) : 0, 0);
    }
    iv_shape c = cone(2, 0, 2);
    iv_shape_normal(&c, (double[3]){1, 0, 1}, IV_PART_CONE_SIDE, n);
    near(n[0], sqrt(0.5), 1e-15);
    near(n[1], 0, 1e-15);
    near(n[2], sqrt(0.5), 1e-15);
    iv_shape_normal(&c, (double[3]){0, 0, 2}, IV_PART_CONE_SIDE, n); /* the apex */
    near(n[2], 1, 0);
    iv_shape_normal(&c, (double[3]){0, 0, 0}, IV_PART_CONE_BOTTOM, n);
    near(n[2], -1, 0);
    iv_shape_normal(&c, (double[3]){0, 0, 2}, IV_PART_CONE_TOP, n);
    near(n[2], 1, 0);
    iv_shape cy = cone(1, 1, 3);
    iv_shape_normal(&cy, (double[3]){0, -1, 2}, IV_PART_CONE_SIDE, n);
    near(n[1], -1, 1e-15);
    near(n[2], 0, 1e-15);
    iv_shape h = halfspace(0, 3, 4, 1);
    iv_shape_normal(&h, (double[3]){0, 0, 0}, IV_PART_SURFACE, n);
    near(n[1], 0.6, 1e-15);
    near(n[2], 0.8, 1e-15);
}

Test(iv_shape, bounds)
{
    double lo[3], hi[3];
    iv_shape s = sphere(2);
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), 0);
    near(lo[0], -2, 0);
    near(hi[2], 2, 0);
    s = sphere(0);
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), -1);
    s = cone(1, 3, 2);
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), 0);
    near(lo[1], -3, 0);
    near(hi[0], 3, 0);
    near(lo[2], 0, 0);
    near(hi[2], 2, 0);
    s = cone(0, 0, 2);
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), -1);
    s = cone(1, 1, 0);
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), -1);
    s = box(0, 0, 0, 1, 0, 1);
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), -1);
    s = halfspace(0, 0, 2, 4);
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), 0);
    near(hi[2], 2, 0);
    cr_assert(isinf(lo[2]) && isinf(hi[0]) && isinf(lo[0]));
    s = halfspace(0, -1, 0, 4);
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), 0);
    near(lo[1], -4, 0);
    s = halfspace(1, 1, 0, 4);
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), 0);
    cr_assert(isinf(hi[0]) && isinf(hi[1]));
    s = halfspace(0, 0, 0, -1);
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), -1);
}

/* ---- shapes: property test against a point classifier -------------------- */

static iv_shape random_shape(void)
{
    switch (rng_int(5)) {
    case 0: {
        double n[3] = {rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1)};
        if (rng_int(2)) n[rng_int(3)] = 0;
        if (rng_int(3) == 0) n[0] = n[1] = 0, n[2] = 1;
        return halfspace(n[0], n[1], n[2], rng_uniform(-1, 1));
    }
    case 1:
        return sphere(rng_uniform(0.2, 2));
    case 2: {
        double a[3], b[3];
        for (int k = 0; k < 3; k++) {
            a[k] = rng_uniform(-2, 1);
            b[k] = a[k] + rng_uniform(0.1, 2);
        }
        return box(a[0], a[1], a[2], b[0], b[1], b[2]);
    }
    default: {
        double r1 = rng_uniform(0, 2), r2 = rng_uniform(0, 2);
        int z = rng_int(4);
        if (z == 0)
            r1 = 0;
        else if (z == 1)
            r2 = 0;
        else if (z == 2)
            r2 = r1;
        return cone(r1, r2, rng_uniform(0.2, 3));
    }
    }
}

/* Directions with exact zeros and exact axis alignment now and then, and
 * origins now and then on the axis or on a face plane. */
static void random_ray(const iv_shape *s, double o[3], double d[3])
{
    for (int k = 0; k < 3; k++) {
        o[k] = rng_uniform(-3, 3);
        d[k] = rng_uniform(-2, 2);
    }
    int z = rng_int(8);
    if (z == 0) {
        d[rng_int(3)] = 0;
    } else if (z == 1) {
        d[0] = d[1] = 0;
    } else if (z == 2 && s->kind == IV_SHAPE_CONE) {
        o[0] = o[1] = 0;
        d[0] = d[1] = 0;
    } else if (z == 3 && s->kind == IV_SHAPE_CONE) {
        /* Aimed at the apex (or the axis point at the far cap). */
        double ap[3] = {0, 0, s->u.cone.r2 == 0 ? s->u.cone.h : 0};
        for (int k = 0; k < 3; k++)
            d[k] = ap[k] - o[k];
    }
}

Test(iv_shape, intersect_matches_point_classifier)
{
    const uint64_t seed = 0x5ea7;
    rng_seed(seed);
    int spans = 0;
    for (int it = 0; it < 40000; it++) {
        iv_arena_reset(arena);
        iv_shape s = random_shape();
        double o[3], d[3];
        random_ray(&s, o, d);
        iv_list l;
        iv_list_init(&l, 1, arena);
        int r = iv_shape_intersect(&s, o, d, 1, &l);
        cr_assert(r == 0 || r == 1, "seed %#llx iter %d", (unsigned long long)seed, it);
        check_invariant(&l, "shape");
        spans += r;
        double dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int k = 0; k < 64; k++) {
            double t = rng_uniform(-6, 6);
            double p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
            double f = shape_sdf(&s, p);
            /* Skip points within 1e-7 of the surface (along the ray or
             * across it), where rounding may legitimately decide. */
            if (fabs(f) < 1e-7) continue;
            int near_bound = 0;
            for (int i = 0; i < l.n; i++)
                if (fabs(t - l.v[i].enter.t) * dl < 1e-7 || fabs(t - l.v[i].exit.t) * dl < 1e-7)
                    near_bound = 1;
            if (near_bound) continue;
            cr_assert_eq(iv_list_contains(&l, t), f < 0,
                         "seed %#llx iter %d kind %d t %.17g: list says %d, classifier %g",
                         (unsigned long long)seed, it, s.kind, t, iv_list_contains(&l, t), f);
        }
    }
    cr_assert(spans > 10000, "too few hits (%d) to mean anything", spans);
}

/* ---- the hierarchy split ------------------------------------------------- */

static void cube_item(iv_bvh_item *it, double x, double y, double z, double h, int id)
{
    const double c[3] = {x, y, z};
    for (int k = 0; k < 3; k++) {
        it->lo[k] = c[k] - h;
        it->hi[k] = c[k] + h;
        it->c[k] = c[k];
    }
    it->id = id;
}

/* Every split keeps the items (a permutation) and leaves both sides
 * nonempty, whatever the layout: random, all centres equal, two items, and
 * past the SAH depth. */
Test(iv_bvh, split_is_a_proper_partition)
{
    enum { N = 300 };
    iv_bvh_item it[N];
    rng_seed(11);
    for (int round = 0; round < 40; round++) {
        int m = 2 + rng_int(N - 1), same = round % 4 == 0;
        for (int i = 0; i < m; i++)
            cube_item(&it[i], same ? 1 : rng_uniform(-50, 50), same ? 2 : rng_uniform(-5, 5),
                      same ? 3 : rng_uniform(0, 500), rng_uniform(0.1, 4), i);
        int l = iv_bvh_split(it, m, round % 3 == 0 ? IV_BVH_SAH_DEPTH : 0);
        cr_assert(l > 0 && l < m, "m %d l %d", m, l);
        int seen[N] = {0};
        for (int i = 0; i < m; i++)
            seen[it[i].id]++;
        for (int i = 0; i < m; i++)
            cr_assert_eq(seen[i], 1, "item %d appears %d times", i, seen[i]);
    }
}

/* Two tight clusters far apart along y: any sensible split separates them,
 * and the area heuristic does — its cost is far below any mixed split's. */
Test(iv_bvh, split_separates_clusters)
{
    enum { N = 64 };
    iv_bvh_item it[N];
    rng_seed(5);
    for (int i = 0; i < N; i++) {
        double y = i % 3 == 0 ? 1000 : 0; /* a third up there, unequal sizes */
        cube_item(&it[i], rng_uniform(0, 1), y + rng_uniform(0, 1), rng_uniform(0, 1), 0.2, i);
    }
    int l = iv_bvh_split(it, N, 0);
    for (int i = 0; i < N; i++) {
        int far = it[i].id % 3 == 0;
        cr_assert_eq(far, it[0].id % 3 == 0 ? i < l : i >= l, "item %d on the wrong side",
                     it[i].id);
    }
}

/* ---- meshes: clipped references ------------------------------------------ */

TestSuite(iv_mesh, .init = arena_setup, .fini = arena_teardown);

#define PI 3.14159265358979323846

/* The faces of a prism over an n-gon whose bottom ring is points 0..n-1
 * and top ring n..2n-1 (as polyhedron() takes them: F the indices, S[i]
 * where face i starts): the bottom, the top reversed, and n quads.
 * Returns the face count, n + 2; F holds 6n indices, S n + 3 entries. */
static int prism_faces(int n, int *F, int *S)
{
    int k = 0, f = 0;
    S[f++] = 0;
    for (int i = 0; i < n; i++)
        F[k++] = i;
    S[f++] = k;
    for (int i = n - 1; i >= 0; i--)
        F[k++] = n + i;
    S[f++] = k;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        F[k++] = i;
        F[k++] = n + i;
        F[k++] = n + j;
        F[k++] = j;
        S[f++] = k;
    }
    return f - 1;
}

enum { TWIST_N = 96 };

/* An n-gon of radius 1 turned by 90° from z = 0 to z = 1 in one slice:
 * 2n side triangles, each a long thin sliver across all three axes, and
 * two planar n-gon ends.  Coordinates are multiples of 2^-10, so the
 * midpoints where references are cut are short binary fractions too, and
 * rays on a 2^-12 grid run in and through the cutting planes. */
static int twisted_prism(iv_shape *s, double extra, long *nref)
{
    static double P[2 * TWIST_N][3];
    static int F[2 * TWIST_N + 4 * TWIST_N], S[TWIST_N + 3];
    for (int i = 0; i < TWIST_N; i++) {
        double a = 2 * PI * i / TWIST_N, b = a + PI / 2;
        P[i][0] = round(1024 * cos(a)) / 1024;
        P[i][1] = round(1024 * sin(a)) / 1024;
        P[i][2] = 0;
        P[TWIST_N + i][0] = round(1024 * cos(b)) / 1024;
        P[TWIST_N + i][1] = round(1024 * sin(b)) / 1024;
        P[TWIST_N + i][2] = 1;
    }
    int nf = prism_faces(TWIST_N, F, S);
    return iv_shape_mesh_budget(s, (const double(*)[3])P, 2 * TWIST_N, F, S, nf, extra, nref);
}

static double grid(double lo, double hi)
{
    return round(rng_uniform(lo, hi) * 4096) / 4096;
}

/* Rays of four kinds: anywhere; along an axis from a grid point; in a grid
 * plane (one direction component zero); from vertex to vertex. */
static void mesh_ray(int kind, double o[3], double d[3])
{
    const double lo[3] = {-1.3, -1.3, -0.3}, hi[3] = {1.3, 1.3, 1.3};
    for (int k = 0; k < 3; k++) {
        o[k] = kind == 0 ? rng_uniform(lo[k], hi[k]) : grid(lo[k], hi[k]);
        d[k] = rng_uniform(-1, 1);
    }
    if (kind == 1) {
        d[0] = d[1] = d[2] = 0;
        d[rng_int(3)] = rng_int(2) ? 1 : -1;
    } else if (kind == 2) {
        d[rng_int(3)] = 0;
    } else if (kind == 3) {
        int a = rng_int(2 * TWIST_N), b = rng_int(2 * TWIST_N);
        double ang[2] = {2 * PI * (a % TWIST_N) / TWIST_N + (a >= TWIST_N ? PI / 2 : 0),
                         2 * PI * (b % TWIST_N) / TWIST_N + (b >= TWIST_N ? PI / 2 : 0)};
        double pa[3] = {round(1024 * cos(ang[0])) / 1024, round(1024 * sin(ang[0])) / 1024,
                        a >= TWIST_N};
        double pb[3] = {round(1024 * cos(ang[1])) / 1024, round(1024 * sin(ang[1])) / 1024,
                        b >= TWIST_N};
        for (int k = 0; k < 3; k++) {
            d[k] = pb[k] - pa[k];
            o[k] = pa[k] - d[k];
        }
    }
}

/* A triangle met through several of its references is one crossing: the
 * lists equal those of the unclipped hierarchy bitwise (t, sign), for rays
 * that lie in cutting planes, cross them on box edges, and pass through
 * vertices.  The parts differ (the triangles are stored in another order). */
Test(iv_mesh, clipped_references_give_the_same_crossings)
{
    iv_shape plain, clipped[2];
    long nplain = 0, nref[2] = {0, 0};
    cr_assert_eq(twisted_prism(&plain, 0, &nplain), 0);
    cr_assert_eq(twisted_prism(&clipped[0], 3, &nref[0]), 0);
    cr_assert_eq(twisted_prism(&clipped[1], 16, &nref[1]), 0);
    cr_assert_eq(nplain, 4 * TWIST_N - 4, "one reference per triangle");
    cr_assert(nref[0] == 4 * nplain && nref[1] > 12 * nplain, "references %ld and %ld of %ld",
              nref[0], nref[1], nplain);
    const uint64_t seed = 0x7157;
    rng_seed(seed);
    int spans = 0;
    for (int it = 0; it < 40000; it++) {
        iv_arena_reset(arena);
        double o[3], d[3];
        mesh_ray(it % 4, o, d);
        iv_list a;
        cr_assert_eq(iv_list_init(&a, iv_shape_max_spans(&plain), arena), 0);
        int ra = iv_shape_intersect(&plain, o, d, 3, &a);
        cr_assert(ra >= 0);
        check_invariant(&a, "plain");
        spans += ra;
        for (int c = 0; c < 2; c++) {
            iv_list b;
            cr_assert_eq(iv_list_init(&b, iv_shape_max_spans(&clipped[c]), arena), 0);
            int rb = iv_shape_intersect(&clipped[c], o, d, 3, &b);
            cr_assert_eq(rb, ra, "seed %#llx iter %d budget %d: %d spans, unclipped %d",
                         (unsigned long long)seed, it, c, rb, ra);
            for (int i = 0; i < ra; i++) {
                const iv_span *x = &a.v[i], *y = &b.v[i];
                cr_assert(x->enter.t == y->enter.t && x->exit.t == y->exit.t,
                          "seed %#llx iter %d budget %d span %d: [%.17g, %.17g] vs [%.17g, %.17g]",
                          (unsigned long long)seed, it, c, i, y->enter.t, y->exit.t, x->enter.t,
                          x->exit.t);
                cr_assert(y->enter.prim == 3 && y->exit.prim == 3 &&
                          x->enter.flip == y->enter.flip && x->exit.flip == y->exit.flip);
            }
        }
    }
    cr_assert(spans > 10000, "too few hits (%d) to mean anything", spans);
    iv_shape_release(&plain);
    iv_shape_release(&clipped[0]);
    iv_shape_release(&clipped[1]);
}

/* A star prism: its ends are concave 2n-gons, cut into triangles by
 * diagonals that leave the face, whose signed cover must still be exactly
 * the face.  Checked against an even-odd point test. */
enum { STAR_N = 2 * 17 };

static void star_point(int k, double p[2])
{
    double r = k % 2 ? 0.35 : 1, a = 2 * PI * k / STAR_N;
    p[0] = r * cos(a);
    p[1] = r * sin(a);
}

/* The signed distance to the star prism's boundary (< 0 inside), exact
 * enough to skip points within 1e-7 of it. */
static double star_sdf(const double p[3])
{
    int inside = 0;
    double dmin = INFINITY;
    for (int i = 0; i < STAR_N; i++) {
        double a[2], b[2];
        star_point(i, a);
        star_point((i + 1) % STAR_N, b);
        if ((a[1] > p[1]) != (b[1] > p[1]) &&
            p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
            inside = !inside;
        double ex = b[0] - a[0], ey = b[1] - a[1];
        double u = ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / (ex * ex + ey * ey);
        u = u < 0 ? 0 : u > 1 ? 1 : u;
        dmin = fmin(dmin, hypot(p[0] - a[0] - u * ex, p[1] - a[1] - u * ey));
    }
    double d2 = inside ? -dmin : dmin, dz = fmax(-p[2], p[2] - 1);
    return d2 > 0 && dz > 0 ? hypot(d2, dz) : fmax(d2, dz);
}

Test(iv_mesh, concave_ends_by_diagonals_match_point_test)
{
    double P[2 * STAR_N][3];
    int F[2 * STAR_N + 4 * STAR_N], S[STAR_N + 3];
    for (int i = 0; i < STAR_N; i++) {
        star_point(i, P[i]);
        P[STAR_N + i][0] = P[i][0];
        P[STAR_N + i][1] = P[i][1];
        P[i][2] = 0;
        P[STAR_N + i][2] = 1;
    }
    int nf = prism_faces(STAR_N, F, S);
    iv_shape s;
    cr_assert_eq(iv_shape_mesh(&s, (const double(*)[3])P, 2 * STAR_N, F, S, nf), 0);
    const uint64_t seed = 0x57a2;
    rng_seed(seed);
    int spans = 0;
    for (int it = 0; it < 20000; it++) {
        iv_arena_reset(arena);
        double o[3], d[3];
        for (int j = 0; j < 3; j++) {
            o[j] = rng_uniform(-1.5, 1.5);
            d[j] = rng_uniform(-1, 1);
        }
        if (it % 3 == 0) d[0] = d[1] = 0; /* through both ends */
        iv_list l;
        cr_assert_eq(iv_list_init(&l, iv_shape_max_spans(&s), arena), 0);
        int r = iv_shape_intersect(&s, o, d, 1, &l);
        cr_assert(r >= 0);
        check_invariant(&l, "star");
        spans += r;
        double dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int q = 0; q < 32; q++) {
            double t = rng_uniform(-4, 4);
            double p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
            double sd = star_sdf(p);
            if (fabs(sd) < 1e-7) continue;
            int near_bound = 0;
            for (int i = 0; i < l.n; i++)
                if (fabs(t - l.v[i].enter.t) * dl < 1e-7 || fabs(t - l.v[i].exit.t) * dl < 1e-7)
                    near_bound = 1;
            if (near_bound) continue;
            cr_assert_eq(iv_list_contains(&l, t), sd < 0,
                         "seed %#llx iter %d t %.17g: list says %d, point test %g",
                         (unsigned long long)seed, it, t, iv_list_contains(&l, t), sd);
        }
    }
    cr_assert(spans > 5000, "too few hits (%d) to mean anything", spans);
    iv_shape_release(&s);
}

/*
 * shape_check.h — an independent check of a shape's interval lists, shared
 * by the suites that build shapes (intervals, geom, scad): random lines
 * through a box (every tenth axis-aligned through the half-unit grid, to hit
 * vertices and edges exactly), each list's spans ordered and non-empty, and
 * membership of random points on each line against a point classifier.
 * Header-only, on support.h's seeded stream and arena.
 */
#ifndef RAYSCAD_TESTS_SHAPE_CHECK_H
#define RAYSCAD_TESTS_SHAPE_CHECK_H

#include "support.h"

typedef int (*classify_fn)(const double p[3], const void *ud);

/* Intersect s with `rays` random lines through the box [-R, R]³ and compare
 * membership of random points on each line with classify(), away from the
 * boundaries (a relative 1e-7).  Returns the number of disagreements. */
static inline int check_shape(const iv_shape *s, classify_fn classify, const void *ud, double R,
                              int rays, uint64_t seed)
{
    rng_seed(seed);
    int bad = 0;
    for (int r = 0; r < rays; r++) {
        iv_arena_reset(arena);
        double o[3], d[3];
        for (int k = 0; k < 3; k++) {
            o[k] = rng_uniform(-R, R);
            d[k] = rng_uniform(-1, 1);
        }
        if (r % 10 == 0) {
            int ax = (int)(rng_next() % 3);
            for (int k = 0; k < 3; k++) {
                o[k] = 0.5 * floor(rng_uniform(-2 * R, 2 * R));
                d[k] = k == ax ? 1 : 0;
            }
        }
        iv_list l;
        int cap = iv_shape_max_spans(s);
        cr_assert_eq(iv_list_init(&l, cap, arena), 0);
        int n = iv_shape_intersect(s, o, d, 3, &l);
        cr_assert(n >= 0, "seed %llu ray %d: room", (unsigned long long)seed, r);
        for (int i = 0; i < l.n; i++) {
            cr_assert(l.v[i].enter.t < l.v[i].exit.t, "seed %llu ray %d: empty span",
                      (unsigned long long)seed, r);
            if (i > 0)
                cr_assert(l.v[i - 1].exit.t < l.v[i].enter.t, "seed %llu ray %d: order",
                          (unsigned long long)seed, r);
        }
        for (int k = 0; k < 40; k++) {
            double t = rng_uniform(-4 * R, 4 * R);
            int close = 0;
            for (int i = 0; i < l.n; i++)
                if (fabs(t - l.v[i].enter.t) < 1e-7 * (1 + fabs(t)) ||
                    fabs(t - l.v[i].exit.t) < 1e-7 * (1 + fabs(t)))
                    close = 1;
            if (close) continue;
            double p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
            int want = classify(p, ud), edge = 0;
            /* a point on the boundary (a line lying in a face) is no test */
            for (int a = 0; a < 6 && !edge; a++) {
                double q[3] = {p[0], p[1], p[2]};
                q[a / 2] += (a & 1 ? 1e-9 : -1e-9) * (1 + fabs(q[a / 2]));
                edge = classify(q, ud) != want;
            }
            if (edge) continue;
            if (want != iv_list_contains(&l, t)) {
                if (bad < 5)
                    cr_log_warn("seed %llu ray %d t %g: classify %d list %d",
                                (unsigned long long)seed, r, t, want, !want);
                bad++;
            }
        }
    }
    return bad;
}

/* classify_fn of the box ud = {lo[3], hi[3]}. */
static inline int in_box(const double p[3], const void *ud)
{
    const double *b = ud;
    for (int k = 0; k < 3; k++)
        if (p[k] < b[k] || p[k] > b[3 + k]) return 0;
    return 1;
}

#endif

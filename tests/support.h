/*
 * support.h — what several Criterion suites share: a seeded splitmix64
 * stream (every random test draws the same cases on every run), one
 * interval arena per test, an independent inside/outside classifier for
 * the analytic shapes, and a tolerance assertion that prints both values.
 * Header-only; each test binary gets its own copy.
 */
#ifndef RAYSCAD_TESTS_SUPPORT_H
#define RAYSCAD_TESTS_SUPPORT_H

#include <criterion/criterion.h>

#include <math.h>
#include <stdint.h>

#include "../src/intervals/intervals.h"

static uint64_t rng_state;

static inline void rng_seed(uint64_t s)
{
    rng_state = s;
}

/* splitmix64 */
static inline uint64_t rng_next(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* Uniform in [lo, hi), from the top 53 bits. */
static inline double rng_uniform(double lo, double hi)
{
    return lo + (hi - lo) * ((double)(rng_next() >> 11) / 9007199254740992.0);
}

static inline int rng_int(int n)
{
    return (int)(rng_next() % (uint64_t)n);
}

/* The test's arena: .init = arena_setup, .fini = arena_teardown. */
static iv_arena *arena;

static inline void arena_setup(void)
{
    arena = iv_arena_new(0);
}

static inline void arena_teardown(void)
{
    iv_arena_free(arena);
}

/* The analytic shapes in their object frames. */
static inline iv_shape sphere(double r)
{
    iv_shape s = {.kind = IV_SHAPE_SPHERE};
    s.u.sphere.r = r;
    return s;
}

static inline iv_shape box(double x0, double y0, double z0, double x1, double y1, double z1)
{
    iv_shape s = {.kind = IV_SHAPE_BOX};
    s.u.box.lo[0] = x0;
    s.u.box.lo[1] = y0;
    s.u.box.lo[2] = z0;
    s.u.box.hi[0] = x1;
    s.u.box.hi[1] = y1;
    s.u.box.hi[2] = z1;
    return s;
}

static inline iv_shape cone(double r1, double r2, double h)
{
    iv_shape s = {.kind = IV_SHAPE_CONE};
    s.u.cone.r1 = r1;
    s.u.cone.r2 = r2;
    s.u.cone.h = h;
    return s;
}

static inline iv_shape halfspace(double nx, double ny, double nz, double d)
{
    iv_shape s = {.kind = IV_SHAPE_HALFSPACE};
    s.u.halfspace.n[0] = nx;
    s.u.halfspace.n[1] = ny;
    s.u.halfspace.n[2] = nz;
    s.u.halfspace.d = d;
    return s;
}

/* Signed "distance-like" value: < 0 inside, > 0 outside.  Not a true
 * distance, but within a factor of the shapes' slopes of one, which is all a
 * margin test needs. */
static inline double shape_sdf(const iv_shape *s, const double p[3])
{
    switch (s->kind) {
    case IV_SHAPE_HALFSPACE: {
        const double *n = s->u.halfspace.n;
        return (n[0] * p[0] + n[1] * p[1] + n[2] * p[2] - s->u.halfspace.d) /
               sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    case IV_SHAPE_SPHERE:
        return sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - s->u.sphere.r;
    case IV_SHAPE_BOX: {
        double m = -INFINITY;
        for (int k = 0; k < 3; k++) {
            m = fmax(m, s->u.box.lo[k] - p[k]);
            m = fmax(m, p[k] - s->u.box.hi[k]);
        }
        return m;
    }
    case IV_SHAPE_CONE: {
        double r1 = s->u.cone.r1, r2 = s->u.cone.r2, h = s->u.cone.h;
        double rz = r1 + (r2 - r1) * p[2] / h;
        double side =
            (sqrt(p[0] * p[0] + p[1] * p[1]) - rz) / sqrt(1 + (r2 - r1) * (r2 - r1) / (h * h));
        return fmax(fmax(-p[2], p[2] - h), side);
    }
    default: /* kinds these tests do not generate */
        break;
    }
    return 1;
}

#define near(x, y, eps)                                                                            \
    cr_assert(fabs((x) - (y)) <= (eps), "%s = %.17g, want %.17g", #x, (double)(x), (double)(y))

#endif

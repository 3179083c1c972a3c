/*
 * test_hull.c — the convex hull (src/geom/hull3d.c): quickhull against the
 * plain incremental algorithm and against the points themselves (each
 * inside every plane, the vertices extreme along random directions), on
 * random, gridded, near-duplicate and near-coplanar points.  Property tests
 * print their seed.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "../../src/intervals/intervals.h"
#include "../../src/io/io.h"
#include "../../src/geom/hull3d.h"
#include "../../src/geom/hull3d_internal.h"
#include "../../src/scad/scad.h"
#include "../services.h"
#include "../shape_check.h"

#define PI 3.14159265358979323846

/* ---- polytope, hull ------------------------------------------------------------- */

/* ---- hull3d (src/scad: quickhull) -------------------------------------------------- */

static int cmp_point(const void *a, const void *b)
{
    const double *p = a, *q = b;
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
    return 0;
}

/* The largest distance of any of the n points above a plane of s. */
static double farthest_outside(const iv_shape *s, const double (*P)[3], int n)
{
    int np;
    const double(*pl)[4] = iv_polytope_planes(s, &np);
    double worst = -INFINITY;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < np; j++)
            worst = fmax(worst,
                         pl[j][0] * P[i][0] + pl[j][1] * P[i][1] + pl[j][2] * P[i][2] - pl[j][3]);
    return worst;
}

Test(polytope, hull_of_cube_and_inner_points, .init = arena_setup, .fini = arena_teardown)
{
    double P[40][3];
    int n = 0;
    for (int i = 0; i < 8; i++) {
        P[n][0] = (i & 1) ? 2 : -1;
        P[n][1] = (i & 2) ? 1 : -1;
        P[n][2] = (i & 4) ? 3 : 0;
        n++;
    }
    rng_state = 5;
    while (n < 40) {
        P[n][0] = rng_uniform(-1, 2);
        P[n][1] = rng_uniform(-1, 1);
        P[n][2] = rng_uniform(0, 3);
        n++;
    }
    iv_shape s;
    cr_assert_eq(geom_hull3d_incremental(&s, (const double(*)[3])P, n), 0);
    int nv;
    iv_polytope_vertices(&s, &nv);
    cr_expect_eq(nv, 8);
    double box[6] = {-1, -1, 0, 2, 1, 3};
    cr_expect_eq(check_shape(&s, in_box, box, 4, 400, 12), 0);
    iv_shape_release(&s);
    /* flat input has no hull */
    double F[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    cr_expect_eq(geom_hull3d_incremental(&s, (const double(*)[3])F, 4), -1);
}

/* The hull of points on a sphere is inside the sphere and contains the
 * sphere shrunk by the chord sagitta. */
Test(polytope, hull_of_sphere_points, .init = arena_setup, .fini = arena_teardown)
{
    enum { N = 300 };
    double P[N][3];
    rng_state = 9;
    for (int i = 0; i < N; i++) {
        double z = rng_uniform(-1, 1), a = rng_uniform(0, 2 * PI), r = sqrt(1 - z * z);
        P[i][0] = 5 * r * cos(a);
        P[i][1] = 5 * r * sin(a);
        P[i][2] = 5 * z;
    }
    iv_shape s;
    cr_assert_eq(geom_hull3d_incremental(&s, (const double(*)[3])P, N), 0);
    int nv;
    iv_polytope_vertices(&s, &nv);
    cr_expect_eq(nv, N); /* points on a sphere are all extreme */
    for (int i = 0; i < 200; i++) {
        double o[3] = {rng_uniform(-6, 6), rng_uniform(-6, 6), rng_uniform(-6, 6)},
               d[3] = {rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1)};
        iv_list l;
        iv_list_init(&l, 1, arena);
        if (iv_shape_intersect(&s, o, d, 0, &l) != 1) continue;
        for (int e = 0; e < 2; e++) {
            double t = e ? l.v[0].exit.t : l.v[0].enter.t;
            double p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
            double r = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            cr_expect(r <= 5 + 1e-9, "boundary outside the sphere: %g", r);
        }
    }
    iv_shape_release(&s);
}

/* Random points (in a ball, on a sphere): geom_hull3d has the vertices
 * polytope.c's brute-force hull (every point against every face) finds, on
 * a subset of 1500, and every point of a set of 100,000 inside its planes,
 * its vertices the extreme points along random directions. */
Test(hull3d, random_points_against_brute_force, .init = arena_setup, .fini = arena_teardown)
{
    enum { N = 100000, SUB = 1500 };
    static double P[N][3], A[N][3], B[N][3];
    for (int kind = 0; kind < 2; kind++) {
        uint64_t seed = 41 + (uint64_t)kind;
        rng_state = seed;
        for (int i = 0; i < N; i++) {
            double z = rng_uniform(-1, 1), a = rng_uniform(0, 2 * PI), r = sqrt(1 - z * z);
            double len = kind ? 1 : cbrt(rng_uniform(0, 1));
            P[i][0] = 3 + 10 * len * r * cos(a);
            P[i][1] = -2 + 10 * len * r * sin(a);
            P[i][2] = 10 * len * z;
        }
        iv_shape h, ref;
        cr_assert_eq(geom_hull3d(&h, (const double(*)[3])P, SUB), 0, "seed %llu",
                     (unsigned long long)seed);
        cr_assert_eq(geom_hull3d_incremental(&ref, (const double(*)[3])P, SUB), 0);
        int na, nb;
        const double(*VA)[3] = iv_polytope_vertices(&h, &na);
        const double(*VB)[3] = iv_polytope_vertices(&ref, &nb);
        cr_assert_eq(na, nb, "seed %llu: %d vertices, brute force %d", (unsigned long long)seed, na,
                     nb);
        memcpy(A, VA, sizeof *A * (size_t)na);
        memcpy(B, VB, sizeof *B * (size_t)nb);
        qsort(A, (size_t)na, sizeof *A, cmp_point);
        qsort(B, (size_t)nb, sizeof *B, cmp_point);
        cr_expect(memcmp(A, B, sizeof *A * (size_t)na) == 0, "seed %llu: other vertices",
                  (unsigned long long)seed);
        iv_shape_release(&h);
        iv_shape_release(&ref);

        int n = kind ? 20000 : N; /* sphere points are all vertices */
        cr_assert_eq(geom_hull3d(&h, (const double(*)[3])P, n), 0);
        double out = farthest_outside(&h, (const double(*)[3])P, kind ? 2000 : n);
        /* within the tolerance: 1e-11 of the coordinates */
        cr_expect(out <= 1e-9, "seed %llu: a point %g outside", (unsigned long long)seed, out);
        const double(*V)[3] = iv_polytope_vertices(&h, &na);
        if (kind) cr_expect_eq(na, n, "seed %llu", (unsigned long long)seed);
        for (int t = 0; t < 50; t++) {
            double d[3] = {rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1)},
                   best = -INFINITY, got = -INFINITY;
            for (int i = 0; i < n; i++)
                best = fmax(best, d[0] * P[i][0] + d[1] * P[i][1] + d[2] * P[i][2]);
            for (int i = 0; i < na; i++)
                got = fmax(got, d[0] * V[i][0] + d[1] * V[i][1] + d[2] * V[i][2]);
            cr_expect(fabs(got - best) <= 1e-9, "seed %llu: support %g, points %g",
                      (unsigned long long)seed, got, best);
        }
        iv_shape_release(&h);
    }
}

/* Exact coplanar input (a grid, a cube's faces subdivided): the solid is
 * the box, as polytope.c makes it; flat, too few and non-finite points make
 * nothing. */
Test(hull3d, grid_is_its_box_and_bad_input_fails, .init = arena_setup, .fini = arena_teardown)
{
    static double P[6 * 6 * 6][3];
    int n = 0;
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 6; j++)
            for (int k = 0; k < 6; k++) {
                P[n][0] = i * 0.4 - 1;
                P[n][1] = j * 0.2 - 1;
                P[n][2] = k * 0.6;
                n++;
            }
    iv_shape s;
    cr_assert_eq(geom_hull3d(&s, (const double(*)[3])P, n), 0);
    double box[6] = {-1, -1, 0, 1, 0, 3};
    cr_expect_eq(check_shape(&s, in_box, box, 4, 400, 13), 0);
    cr_expect(farthest_outside(&s, (const double(*)[3])P, n) <= 1e-12);
    iv_shape_release(&s);
    double F[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 5, 0}};
    cr_expect_eq(geom_hull3d(&s, (const double(*)[3])F, 5), GEOM_HULL_FLAT);
    cr_expect_eq(geom_hull3d(&s, (const double(*)[3])F, 3), GEOM_HULL_FLAT);
    F[4][2] = NAN;
    cr_expect_eq(geom_hull3d(&s, (const double(*)[3])F, 5), GEOM_HULL_BAD_INPUT);
}

/* Rounding's worst cases: corners of 0.1 cubes around a cylinder, each
 * moved by up to 1e-9 (points a few eps apart), and points on a cube's
 * faces off them by up to 2e-11 (coplanar to a few eps).  Every point
 * stays within a relative 1e-7 of the hull (polytope.c's hull is off by up
 * to the whole size on these, or takes minutes). */
Test(hull3d, near_duplicate_and_near_coplanar_points, .init = arena_setup, .fini = arena_teardown)
{
    enum { N = 3000 };
    static double P[N][3];
    for (int kind = 0; kind < 2; kind++)
        for (uint64_t seed = 1; seed <= 10; seed++) {
            rng_state = seed + 100 * (uint64_t)kind;
            for (int i = 0; i < N; i++) {
                if (kind == 0) {
                    double a = (i % 360) * PI / 180;
                    P[i][0] = 10 * cos(a) + (i & 1) * 0.1 + rng_uniform(-1e-9, 1e-9);
                    P[i][1] = 10 * sin(a) + (i >> 1 & 1) * 0.1 + rng_uniform(-1e-9, 1e-9);
                    P[i][2] = i % 10 + (i >> 2 & 1) * 0.1 + rng_uniform(-1e-9, 1e-9);
                } else {
                    int f = (int)rng_uniform(0, 6);
                    for (int k = 0; k < 3; k++)
                        P[i][k] = rng_uniform(-1, 1);
                    P[i][f % 3] = (f < 3 ? -1 : 1) + rng_uniform(-2e-11, 2e-11);
                }
            }
            iv_shape h;
            cr_assert_eq(geom_hull3d(&h, (const double(*)[3])P, N), 0, "kind %d seed %llu", kind,
                         (unsigned long long)seed);
            double out = farthest_outside(&h, (const double(*)[3])P, N), size = kind ? 1 : 10;
            cr_expect(out <= 1e-7 * size, "kind %d seed %llu: a point %g outside", kind,
                      (unsigned long long)seed, out);
            int nv;
            const double(*V)[3] = iv_polytope_vertices(&h, &nv);
            for (int t = 0; t < 20; t++) {
                double d[3] = {rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1)},
                       best = -INFINITY, got = -INFINITY;
                for (int i = 0; i < N; i++)
                    best = fmax(best, d[0] * P[i][0] + d[1] * P[i][1] + d[2] * P[i][2]);
                for (int i = 0; i < nv; i++)
                    got = fmax(got, d[0] * V[i][0] + d[1] * V[i][1] + d[2] * V[i][2]);
                cr_expect(best - got <= 1e-7 * size, "kind %d seed %llu: support %g, points %g",
                          kind, (unsigned long long)seed, got, best);
            }
            iv_shape_release(&h);
        }
}

/* Whether p lies inside every plane of polytope ud (an iv_shape). */
static int in_planes(const double p[3], const void *ud)
{
    int n;
    const double(*pl)[4] = iv_polytope_planes(ud, &n);
    for (int i = 0; i < n; i++)
        if (pl[i][0] * p[0] + pl[i][1] * p[1] + pl[i][2] * p[2] > pl[i][3]) return 0;
    return 1;
}

/* Lines walk over a large hull's faces (polytope.c) instead of clipping
 * against each plane: the spans must be the clipping's, here redone by the
 * test against the planes.  The hull: points on a sphere with a flat cap
 * of 64 points (a 64-gon face: many coplanar triangles, whose shared edges
 * bound nothing), from both hull builders.  The lines: random ones, every
 * tenth along an axis (shape_check), then rows of parallel lines as the
 * mesher and renderer cast them (each walk starts where the last ended),
 * in many directions, a third of them grazing the sphere. */
Test(hull3d, walked_lines_as_clipped, .init = arena_setup, .fini = arena_teardown)
{
    enum { N = 1200, CAP = 64 };
    static double P[N + CAP][3];
    uint64_t seed = 77;
    rng_state = seed;
    for (int i = 0; i < N; i++) {
        double z = rng_uniform(-1, 0.6), a = rng_uniform(0, 2 * PI), r = sqrt(1 - z * z);
        P[i][0] = 5 * r * cos(a);
        P[i][1] = 5 * r * sin(a);
        P[i][2] = 5 * z;
    }
    for (int i = 0; i < CAP; i++) {
        double a = 2 * PI * i / CAP;
        P[N + i][0] = 4 * cos(a);
        P[N + i][1] = 4 * sin(a);
        P[N + i][2] = 3;
    }
    for (int builder = 0; builder < 2; builder++) {
        iv_shape h;
        int built = builder ? geom_hull3d_incremental(&h, (const double(*)[3])P, N + CAP)
                            : geom_hull3d(&h, (const double(*)[3])P, N + CAP);
        cr_assert_eq(built, 0);
        int np;
        const double(*pl)[4] = iv_polytope_planes(&h, &np);
        cr_assert_gt(np, 1000);
        cr_expect_eq(check_shape(&h, in_planes, &h, 6, 3000, seed + (uint64_t)builder), 0,
                     "builder %d", builder);
        int bad = 0, hits = 0;
        for (int dir = 0; dir < 40; dir++) {
            double d[3] = {rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1)}, e1[3],
                   e2[3], dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            for (int k = 0; k < 3; k++)
                d[k] /= dl;
            /* e1, e2 across d */
            double a[3] = {fabs(d[0]) < 0.6 ? 1 : 0, fabs(d[0]) < 0.6 ? 0 : 1, 0};
            e1[0] = a[1] * d[2] - a[2] * d[1];
            e1[1] = a[2] * d[0] - a[0] * d[2];
            e1[2] = a[0] * d[1] - a[1] * d[0];
            double l1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
            for (int k = 0; k < 3; k++)
                e1[k] /= l1;
            e2[0] = d[1] * e1[2] - d[2] * e1[1];
            e2[1] = d[2] * e1[0] - d[0] * e1[2];
            e2[2] = d[0] * e1[1] - d[1] * e1[0];
            double reach = dir % 3 == 0 ? 5.2 : 7; /* a third of the rows near the rim */
            for (int i = 0; i < 30; i++)
                for (int j = 0; j < 30; j++) {
                    double u = -reach + 2 * reach * i / 29, v = -reach + 2 * reach * j / 29, o[3];
                    for (int k = 0; k < 3; k++)
                        o[k] = u * e1[k] + v * e2[k] - 20 * d[k];
                    double t0 = -INFINITY, t1 = INFINITY;
                    for (int q = 0; q < np; q++) {
                        double dn = pl[q][0] * d[0] + pl[q][1] * d[1] + pl[q][2] * d[2];
                        double c = pl[q][0] * o[0] + pl[q][1] * o[1] + pl[q][2] * o[2] - pl[q][3];
                        if (dn < 0)
                            t0 = fmax(t0, -c / dn);
                        else if (dn > 0)
                            t1 = fmin(t1, -c / dn);
                        else if (c > 0)
                            t0 = INFINITY;
                    }
                    iv_arena_reset(arena);
                    iv_list l;
                    cr_assert_eq(iv_list_init(&l, iv_shape_max_spans(&h), arena), 0);
                    int n = iv_shape_intersect(&h, o, d, 0, &l);
                    int want = t0 < t1;
                    hits += want;
                    /* a line grazing an edge may go either way */
                    if (want && t1 - t0 < 1e-9) continue;
                    if (n != want || (n && (fabs(l.v[0].enter.t - t0) > 1e-9 ||
                                            fabs(l.v[0].exit.t - t1) > 1e-9))) {
                        if (bad < 5)
                            cr_log_warn("builder %d dir %d (%d, %d): %d [%.12g, %.12g], clipped "
                                        "%d [%.12g, %.12g]",
                                        builder, dir, i, j, n, n ? l.v[0].enter.t : 0,
                                        n ? l.v[0].exit.t : 0, want, t0, t1);
                        bad++;
                    }
                }
        }
        cr_expect_eq(bad, 0, "builder %d: %d lines differ", builder, bad);
        cr_expect_gt(hits, 10000);
        iv_shape_release(&h);
    }
}

/*
 * test_geometry.c — the shapes with shared data (polytope, hull, mesh,
 * prism, revolve): their interval lists along random lines against an
 * independent point classifier, watertightness on lines through vertices and
 * edges, and reference counting.  Property tests print their seed.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "../src/intervals/intervals.h"
#include "../src/io/io.h"
#include "../src/geom/hull3d.h"
#include "../src/scad/scad.h"
#include "services.h"

#define PI 3.14159265358979323846

static uint64_t rng_state;
static uint64_t rng_next(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}
static double uni(double lo, double hi)
{
    return lo + (hi - lo) * ((double)(rng_next() >> 11) / 9007199254740992.0);
}

static iv_arena *arena;
static void setup(void)
{
    arena = iv_arena_new(0);
}
static void teardown(void)
{
    iv_arena_free(arena);
}

typedef int (*classify_fn)(const double p[3], const void *ud);

/* Intersect s with `rays` random lines through the box [-R, R]³ and compare
 * membership of random points on each line with classify(), away from the
 * boundaries (a relative 1e-7).  Returns the number of disagreements. */
static int check_shape(const iv_shape *s, classify_fn classify, const void *ud, double R, int rays,
                       uint64_t seed)
{
    rng_state = seed;
    int bad = 0;
    for (int r = 0; r < rays; r++) {
        iv_arena_reset(arena);
        double o[3], d[3];
        for (int k = 0; k < 3; k++) {
            o[k] = uni(-R, R);
            d[k] = uni(-1, 1);
        }
        /* every tenth line axis-aligned, through the grid of half-units,
         * to hit vertices and edges exactly */
        if (r % 10 == 0) {
            int ax = (int)(rng_next() % 3);
            for (int k = 0; k < 3; k++) {
                o[k] = 0.5 * floor(uni(-2 * R, 2 * R));
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
            double t = uni(-4 * R, 4 * R);
            int near = 0;
            for (int i = 0; i < l.n; i++)
                if (fabs(t - l.v[i].enter.t) < 1e-7 * (1 + fabs(t)) ||
                    fabs(t - l.v[i].exit.t) < 1e-7 * (1 + fabs(t)))
                    near = 1;
            if (near) continue;
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

/* ---- polytope, hull ------------------------------------------------------------- */

static int in_box(const double p[3], const void *ud)
{
    const double *b = ud; /* lo[3], hi[3] */
    for (int k = 0; k < 3; k++)
        if (p[k] < b[k] || p[k] > b[3 + k]) return 0;
    return 1;
}

Test(polytope, box_planes, .init = setup, .fini = teardown)
{
    const double pl[6][4] = {{-1, 0, 0, 1}, {1, 0, 0, 2},  {0, -2, 0, 2},
                             {0, 1, 0, 1},  {0, 0, -1, 0}, {0, 0, 1, 3}};
    const double v[2][3] = {{-1, -1, 0}, {2, 1, 3}};
    iv_shape s;
    cr_assert_eq(iv_shape_polytope(&s, pl, 6, v, 2), 0);
    double box[6] = {-1, -1, 0, 2, 1, 3};
    cr_expect_eq(check_shape(&s, in_box, box, 4, 400, 11), 0);
    double lo[3], hi[3];
    cr_assert_eq(iv_shape_bounds(&s, lo, hi), 0);
    cr_expect_eq(lo[0], -1);
    cr_expect_eq(hi[2], 3);
    double n[3];
    iv_shape_normal(&s, (double[3]){0, 0, 3}, 5, n);
    cr_expect_eq(n[2], 1);
    iv_shape_release(&s);
}

Test(polytope, hull_of_cube_and_inner_points, .init = setup, .fini = teardown)
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
        P[n][0] = uni(-1, 2);
        P[n][1] = uni(-1, 1);
        P[n][2] = uni(0, 3);
        n++;
    }
    iv_shape s;
    cr_assert_eq(iv_shape_hull(&s, (const double(*)[3])P, n), 0);
    int nv;
    iv_polytope_vertices(&s, &nv);
    cr_expect_eq(nv, 8);
    double box[6] = {-1, -1, 0, 2, 1, 3};
    cr_expect_eq(check_shape(&s, in_box, box, 4, 400, 12), 0);
    iv_shape_release(&s);
    /* flat input has no hull */
    double F[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    cr_expect_eq(iv_shape_hull(&s, (const double(*)[3])F, 4), -1);
}

/* The hull of points on a sphere is inside the sphere and contains the
 * sphere shrunk by the chord sagitta. */
Test(polytope, hull_of_sphere_points, .init = setup, .fini = teardown)
{
    enum { N = 300 };
    double P[N][3];
    rng_state = 9;
    for (int i = 0; i < N; i++) {
        double z = uni(-1, 1), a = uni(0, 2 * PI), r = sqrt(1 - z * z);
        P[i][0] = 5 * r * cos(a);
        P[i][1] = 5 * r * sin(a);
        P[i][2] = 5 * z;
    }
    iv_shape s;
    cr_assert_eq(iv_shape_hull(&s, (const double(*)[3])P, N), 0);
    int nv;
    iv_polytope_vertices(&s, &nv);
    cr_expect_eq(nv, N); /* points on a sphere are all extreme */
    for (int i = 0; i < 200; i++) {
        double o[3] = {uni(-6, 6), uni(-6, 6), uni(-6, 6)},
               d[3] = {uni(-1, 1), uni(-1, 1), uni(-1, 1)};
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

/* Random points (in a ball, on a sphere): geom_hull3d has the vertices
 * polytope.c's brute-force hull (every point against every face) finds, on
 * a subset of 1500, and every point of a set of 100,000 inside its planes,
 * its vertices the extreme points along random directions. */
Test(hull3d, random_points_against_brute_force, .init = setup, .fini = teardown)
{
    enum { N = 100000, SUB = 1500 };
    static double P[N][3], A[N][3], B[N][3];
    for (int kind = 0; kind < 2; kind++) {
        uint64_t seed = 41 + (uint64_t)kind;
        rng_state = seed;
        for (int i = 0; i < N; i++) {
            double z = uni(-1, 1), a = uni(0, 2 * PI), r = sqrt(1 - z * z);
            double len = kind ? 1 : cbrt(uni(0, 1));
            P[i][0] = 3 + 10 * len * r * cos(a);
            P[i][1] = -2 + 10 * len * r * sin(a);
            P[i][2] = 10 * len * z;
        }
        iv_shape h, ref;
        cr_assert_eq(geom_hull3d(&h, (const double(*)[3])P, SUB), 0, "seed %llu",
                     (unsigned long long)seed);
        cr_assert_eq(iv_shape_hull(&ref, (const double(*)[3])P, SUB), 0);
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
            double d[3] = {uni(-1, 1), uni(-1, 1), uni(-1, 1)}, best = -INFINITY, got = -INFINITY;
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
Test(hull3d, grid_is_its_box_and_bad_input_fails, .init = setup, .fini = teardown)
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
Test(hull3d, near_duplicate_and_near_coplanar_points, .init = setup, .fini = teardown)
{
    enum { N = 3000 };
    static double P[N][3];
    for (int kind = 0; kind < 2; kind++)
        for (uint64_t seed = 1; seed <= 10; seed++) {
            rng_state = seed + 100 * (uint64_t)kind;
            for (int i = 0; i < N; i++) {
                if (kind == 0) {
                    double a = (i % 360) * PI / 180;
                    P[i][0] = 10 * cos(a) + (i & 1) * 0.1 + uni(-1e-9, 1e-9);
                    P[i][1] = 10 * sin(a) + (i >> 1 & 1) * 0.1 + uni(-1e-9, 1e-9);
                    P[i][2] = i % 10 + (i >> 2 & 1) * 0.1 + uni(-1e-9, 1e-9);
                } else {
                    int f = (int)uni(0, 6);
                    for (int k = 0; k < 3; k++)
                        P[i][k] = uni(-1, 1);
                    P[i][f % 3] = (f < 3 ? -1 : 1) + uni(-2e-11, 2e-11);
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
                double d[3] = {uni(-1, 1), uni(-1, 1), uni(-1, 1)}, best = -INFINITY,
                       got = -INFINITY;
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

/* ---- mesh ------------------------------------------------------------------------ */

/* OpenSCAD's manual cube: points then faces, clockwise from outside. */
static const double cube_pts[8][3] = {{0, 0, 0}, {10, 0, 0}, {10, 7, 0}, {0, 7, 0},
                                      {0, 0, 5}, {10, 0, 5}, {10, 7, 5}, {0, 7, 5}};
static const int cube_faces[] = {0, 1, 2, 3, 4, 5, 1, 0, 7, 6, 5, 4,
                                 5, 6, 2, 1, 6, 7, 3, 2, 7, 4, 0, 3};
static const int cube_start[] = {0, 4, 8, 12, 16, 20, 24};

Test(mesh, manual_cube_matches_box, .init = setup, .fini = teardown)
{
    iv_shape s;
    cr_assert_eq(iv_shape_mesh(&s, cube_pts, 8, cube_faces, cube_start, 6), 0);
    cr_expect_float_eq(iv_mesh_volume(&s), 350, 1e-9);
    double box[6] = {0, 0, 0, 10, 7, 5};
    cr_expect_eq(check_shape(&s, in_box, box, 12, 2000, 21), 0);
    /* the normal of the top face */
    double n[3];
    iv_list l;
    iv_list_init(&l, iv_shape_max_spans(&s), arena);
    cr_assert_eq(iv_shape_intersect(&s, (double[3]){3, 3, 9}, (double[3]){0, 0, -1}, 0, &l), 1);
    cr_expect_float_eq(l.v[0].enter.t, 4, 1e-12);
    iv_shape_normal(&s, (double[3]){3, 3, 5}, l.v[0].enter.part, n);
    cr_expect_float_eq(n[2], 1, 1e-12);
    iv_shape_release(&s);
}

Test(mesh, reversed_winding_is_turned_outside_in, .init = setup, .fini = teardown)
{
    int rev[24];
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < 4; j++)
            rev[4 * f + j] = cube_faces[4 * f + 3 - j];
    iv_shape s;
    cr_assert_eq(iv_shape_mesh(&s, cube_pts, 8, rev, cube_start, 6), 0);
    double box[6] = {0, 0, 0, 10, 7, 5};
    cr_expect_eq(check_shape(&s, in_box, box, 12, 300, 22), 0);
    iv_shape_release(&s);
}

Test(mesh, open_and_bad_input, .init = setup, .fini = teardown)
{
    iv_shape s;
    cr_expect_eq(iv_shape_mesh(&s, cube_pts, 8, cube_faces, cube_start, 5), 1); /* no top */
    iv_shape_release(&s);
    int bad[] = {0, 1, 9};
    int bs[] = {0, 3};
    cr_expect_eq(iv_shape_mesh(&s, cube_pts, 8, bad, bs, 1), -1);
}

/* An L-shaped prism with concave end faces given as single 6-gons, and a
 * fine grid of lines: the fan of a concave face must cover it exactly. */
static int in_L(const double p[3], const void *ud)
{
    (void)ud;
    if (p[2] < 0 || p[2] > 2) return 0;
    int a = p[0] >= 0 && p[0] <= 4 && p[1] >= 0 && p[1] <= 1;
    int b = p[0] >= 0 && p[0] <= 1 && p[1] >= 0 && p[1] <= 3;
    return a || b;
}

Test(mesh, concave_faces_by_fans, .init = setup, .fini = teardown)
{
    /* base outline counter-clockwise from above */
    const double L[6][2] = {{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}};
    double P[12][3];
    for (int i = 0; i < 6; i++) {
        P[i][0] = P[i + 6][0] = L[i][0];
        P[i][1] = P[i + 6][1] = L[i][1];
        P[i][2] = 0;
        P[i + 6][2] = 2;
    }
    int F[6 + 6 + 24], S[9];
    int k = 0, f = 0;
    S[f++] = 0;
    /* bottom seen from below is clockwise when counter-clockwise from above */
    for (int i = 0; i < 6; i++)
        F[k++] = i;
    S[f++] = k;
    for (int i = 5; i >= 0; i--)
        F[k++] = 6 + i;
    S[f++] = k;
    for (int i = 0; i < 6; i++) {
        int j = (i + 1) % 6;
        /* side quad, clockwise from outside */
        F[k++] = i;
        F[k++] = 6 + i;
        F[k++] = 6 + j;
        F[k++] = j;
        S[f++] = k;
    }
    iv_shape s;
    cr_assert_eq(iv_shape_mesh(&s, (const double(*)[3])P, 12, F, S, 8), 0);
    cr_expect_float_eq(iv_mesh_volume(&s), 12, 1e-9);
    cr_expect_eq(check_shape(&s, in_L, NULL, 5, 3000, 23), 0);
    iv_shape_release(&s);
}

/* ---- prism, region ------------------------------------------------------------------ */

/* Independent even-odd test: a 4×4 square with a 2×2 hole, z in [-1, 1]. */
static int in_frame(const double p[3], const void *ud)
{
    (void)ud;
    if (p[2] < -1 || p[2] > 1) return 0;
    int outer = p[0] >= 0 && p[0] <= 4 && p[1] >= 0 && p[1] <= 4;
    int hole = p[0] > 1 && p[0] < 3 && p[1] > 1 && p[1] < 3;
    return outer && !hole;
}

Test(prism, square_with_hole, .init = setup, .fini = teardown)
{
    /* both paths counter-clockwise: the region re-orients the hole */
    const double pts[8][2] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {3, 3}, {1, 3}};
    const int st[3] = {0, 4, 8};
    iv_region *g = iv_region_new(pts, st, 2);
    cr_assert_not_null(g);
    iv_shape s;
    iv_shape_prism(&s, g, -1, 1);
    iv_region_release(g); /* the shape holds its own reference */
    cr_expect_eq(check_shape(&s, in_frame, NULL, 5, 3000, 31), 0);
    /* the hole's wall normal points into the hole */
    iv_list l;
    iv_list_init(&l, iv_shape_max_spans(&s), arena);
    cr_assert_eq(iv_shape_intersect(&s, (double[3]){-1, 2, 0}, (double[3]){1, 0, 0}, 0, &l), 2);
    double n[3];
    iv_shape_normal(&s, (double[3]){1, 2, 0}, l.v[0].exit.part, n);
    cr_expect_float_eq(n[0], 1, 1e-12);
    iv_shape_release(&s);
}

static int in_disc(const double p[3], const void *ud)
{
    (void)ud;
    return p[0] * p[0] + p[1] * p[1] <= 4 && p[2] >= 0 && p[2] <= 3;
}

Test(prism, disc, .init = setup, .fini = teardown)
{
    iv_shape s;
    memset(&s, 0, sizeof s);
    s.kind = IV_SHAPE_PRISM;
    s.u.prism.r = 2;
    s.u.prism.z0 = 0;
    s.u.prism.z1 = 3;
    cr_expect_eq(check_shape(&s, in_disc, NULL, 4, 1000, 32), 0);
}

/* ---- revolve ------------------------------------------------------------------------ */

typedef struct rev_case {
    double angle;
} rev_case;

/* Profile: the triangle (1,0) (3,0) (1,2) and a square hole-free ring. */
static int in_rev(const double p[3], const void *ud)
{
    const rev_case *c = ud;
    double rho = hypot(p[0], p[1]), z = p[2];
    int prof = rho >= 1 && z >= 0 && rho + z <= 3;
    if (!prof) return 0;
    if (c->angle >= 360) return 1;
    double a = atan2(p[1], p[0]) * 180 / PI;
    if (a < 0) a += 360;
    return a <= c->angle;
}

Test(revolve, triangle_profile_full_and_partial, .init = setup, .fini = teardown)
{
    const double pts[3][2] = {{1, 0}, {3, 0}, {1, 2}};
    const int st[2] = {0, 3};
    iv_region *g = iv_region_new(pts, st, 1);
    const double angles[] = {360, 90, 200};
    for (int i = 0; i < 3; i++) {
        iv_shape s;
        iv_shape_revolve(&s, g, angles[i]);
        rev_case c = {angles[i]};
        cr_expect_eq(check_shape(&s, in_rev, &c, 4, 2000, 41 + (uint64_t)i), 0, "angle %g",
                     angles[i]);
        iv_shape_release(&s);
    }
    iv_region_release(g);
}

/* ---- geometry built by the language: twisted extrusion, surface, import,
 * resize — through scad_eval_string and a committed scene ---------------------- */

/* The real services of the command (the OFF header rewrite included):
 * tests link the command's parts other than main. */

typedef struct msgs {
    char text[4096];
} msgs;

static void on_msg(void *ud, scad_msg_kind kind, const char *line)
{
    (void)kind;
    msgs *m = ud;
    size_t n = strlen(m->text);
    snprintf(m->text + n, sizeof m->text - n, "%s\n", line);
}

/* The model of src as a scene (NULL when empty); messages into m. */
static csg_scene *scene_of(const char *src, msgs *m)
{
    scad_options o;
    memset(&o, 0, sizeof o);
    o.message = on_msg;
    o.ud = m;
    o.services = test_services();
    scad_result r;
    cr_assert_eq(scad_eval_string("t.scad", src, &o, &r), 0, "%s", m->text);
    csg_node *root = r.model;
    r.model = NULL;
    scad_result_free(&r);
    char err[256];
    csg_scene *s = csg_scene_new(&root, 1, err, sizeof err);
    cr_assert(s, "%s", err);
    return s;
}

/* Volume by vertical rays through the centres of an n × n grid over the
 * scene's bounds: Σ length inside × cell area.  The error is the boundary
 * band of the grid, O(perimeter · cell). */
static double traced_volume(const csg_scene *s, int n)
{
    double lo[3], hi[3];
    if (csg_scene_bounds(s, 0, lo, hi) != 0) return 0;
    double dx = (hi[0] - lo[0]) / n, dy = (hi[1] - lo[1]) / n, v = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            iv_arena_reset(arena);
            double o[3] = {lo[0] + (i + 0.5) * dx, lo[1] + (j + 0.5) * dy, lo[2] - 1};
            iv_list l;
            cr_assert_eq(csg_trace(s, 0, o, (double[3]){0, 0, 1}, 0, INFINITY, arena, &l), 0);
            for (int k = 0; k < l.n; k++)
                v += (l.v[k].exit.t - l.v[k].enter.t) * dx * dy;
        }
    return v;
}

/* 1 when p is inside root 0 (a vertical ray through it). */
static int scene_contains(const csg_scene *s, const double p[3])
{
    iv_arena_reset(arena);
    iv_list l;
    double o[3] = {p[0], p[1], -1000};
    cr_assert_eq(csg_trace(s, 0, o, (double[3]){0, 0, 1}, 0, INFINITY, arena, &l), 0);
    return iv_list_contains(&l, p[2] + 1000);
}

Test(linear_extrude, twisted_square_volume_is_the_prism_volume, .init = setup, .fini = teardown)
{
    msgs m = {""};
    csg_scene *s = scene_of(
        "linear_extrude(height = 20, twist = 90, slices = 40) square(10, center = true);", &m);
    /* the twisted solid has the untwisted volume, 2000; OpenSCAD's slices
     * split each twisted quad along its shorter diagonal, which bulges out:
     * its own mesh (openscad -o x.off, 2021.01) holds 2025.659 */
    double v = traced_volume(s, 300);
    cr_expect(fabs(v - 2025.659) < 0.001 * 2025.659, "volume %g", v);
    cr_expect(fabs(v - 2000) < 0.015 * 2000, "volume %g", v);
    cr_expect_str_empty(m.text);
    csg_scene_free(s);
}

Test(linear_extrude, scaled_frustum_and_pyramid_volumes, .init = setup, .fini = teardown)
{
    msgs m = {""};
    /* uniform scale alone: one slice, planar faces, a frustum h·A·(1+s+s²)/3 */
    csg_scene *s = scene_of("linear_extrude(12, scale = 0.5) square(10, center = true);", &m);
    double v = traced_volume(s, 300);
    cr_expect(fabs(v - 12 * 100 * 1.75 / 3) < 0.003 * 700, "frustum %g", v);
    csg_scene_free(s);
    /* scale 0: a pyramid, h·A/3, closed at its apex */
    s = scene_of("linear_extrude(9, scale = 0) square(10, center = true);", &m);
    v = traced_volume(s, 300);
    cr_expect(fabs(v - 300) < 0.003 * 300, "pyramid %g", v);
    csg_scene_free(s);
    cr_expect_str_empty(m.text);
}

/* Inside the twisted, scaled square: p's shadow turned back by the twist at
 * its height and scaled back lies in the square; points within `margin` of
 * the boundary are no test (OpenSCAD's flat slices lie within it). */
typedef struct twist_case {
    double h, twist, s1, half, margin;
} twist_case;

static int twist_classify(const double p[3], const twist_case *c, int *sure)
{
    *sure = 0;
    if (p[2] < 0 || p[2] > c->h) {
        *sure = fabs(p[2] - (p[2] < 0 ? 0 : c->h)) > c->margin;
        return 0;
    }
    double f = p[2] / c->h, a = c->twist * f * PI / 180, sc = 1 - (1 - c->s1) * f;
    /* the extrusion turns by -twist·f; undo it */
    double x = (cos(a) * p[0] - sin(a) * p[1]) / sc, y = (sin(a) * p[0] + cos(a) * p[1]) / sc;
    double d = fmin(c->half - fabs(x), c->half - fabs(y)) * sc;
    *sure = fabs(d) > c->margin && fabs(p[2]) > c->margin && fabs(p[2] - c->h) > c->margin;
    return d > 0;
}

Test(linear_extrude, twisted_points_against_the_inverse_map, .init = setup, .fini = teardown)
{
    msgs m = {""};
    csg_scene *s = scene_of("linear_extrude(height = 16, twist = -120, scale = 0.6, slices = 48)"
                            " square(12, center = true);",
                            &m);
    twist_case c = {16, -120, 0.6, 6, 0.08};
    rng_state = 42;
    int bad = 0, tested = 0;
    for (int i = 0; i < 4000; i++) {
        double p[3] = {uni(-9, 9), uni(-9, 9), uni(-2, 18)};
        int certain;
        int want = twist_classify(p, &c, &certain);
        if (!certain) continue;
        tested++;
        if (want != scene_contains(s, p)) {
            if (bad < 5) cr_log_warn("seed 42 p %g %g %g: want %d", p[0], p[1], p[2], want);
            bad++;
        }
    }
    cr_expect(tested > 3000);
    cr_expect_eq(bad, 0);
    csg_scene_free(s);
}

Test(linear_extrude, twist_with_a_hole_and_off_centre_disc, .init = setup, .fini = teardown)
{
    msgs m = {""};
    /* the hole stays empty along its twisted axis; the disc is OpenSCAD's
     * 24-gon swept around the axis (its centre line inside, the axis not) */
    csg_scene *s = scene_of("linear_extrude(10, twist = 180, $fn = 24) difference() {"
                            "  square(12, center = true); circle(3); }"
                            "translate([0, 0, 20]) linear_extrude(10, twist = 90, $fn = 24)"
                            "  translate([5, 0]) circle(2);",
                            &m);
    cr_expect(!scene_contains(s, (double[3]){0, 0, 5}));
    cr_expect(scene_contains(s, (double[3]){5, 5, 0.5}));
    cr_expect(!scene_contains(s, (double[3]){0, 0, 25}));
    for (int k = 0; k <= 10; k++) {
        double z = 20 + k, a = -90.0 * k / 10 * PI / 180;
        cr_expect(scene_contains(s, (double[3]){5 * cos(a), 5 * sin(a), z - (k == 10) * 1e-6}),
                  "k %d", k);
    }
    csg_scene_free(s);
}

Test(surface, dat_and_png_volumes_match_openscad, .init = setup, .fini = teardown)
{
    msgs m = {""};
    /* volumes of `openscad -o x.off` of the same calls (2021.01): 115.5 and
     * 2029.34 (bottoms at min(0, lowest - 1)) */
    csg_scene *s = scene_of("surface(\"tests/models/data/surface.dat\", center = true);", &m);
    double v = traced_volume(s, 400);
    cr_expect(fabs(v - 115.5) < 0.002 * 115.5, "dat %g", v);
    csg_scene_free(s);
    s = scene_of("surface(\"tests/models/data/surface.png\");", &m);
    v = traced_volume(s, 400);
    cr_expect(fabs(v - 2029.34) < 0.002 * 2029.34, "png %g", v);
    csg_scene_free(s);
    cr_expect_str_empty(m.text);
}

Test(import, stl_and_one_line_off_round_trip, .init = setup, .fini = teardown)
{
    char dir[] = "/tmp/rayscad-test-XXXXXX";
    cr_assert(mkdtemp(dir));
    char stl[256], off[256], src[1024];
    snprintf(stl, sizeof stl, "%s/box.stl", dir);
    snprintf(off, sizeof off, "%s/box.off", dir);
    /* the STL: written by io_mesh_write from a plain box (volume 24) */
    const float bv[8][3] = {{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 0},
                            {0, 0, 2}, {4, 0, 2}, {4, 3, 2}, {0, 3, 2}};
    const int32_t bt[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                               {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    char err[256];
    cr_assert_eq(io_mesh_write(stl, &bv[0][0], 8, &bt[0][0], 12, 0, err, sizeof err), 0, "%s", err);
    /* the OFF as OpenSCAD writes it: counts on the header line */
    FILE *f = fopen(off, "w");
    cr_assert(f);
    fprintf(f, "OFF 8 12 0\n");
    for (int i = 0; i < 8; i++)
        fprintf(f, "%g %g %g \n", bv[i][0], bv[i][1], bv[i][2]);
    for (int i = 0; i < 12; i++)
        fprintf(f, "3 %d %d %d\n", bt[i][0], bt[i][1], bt[i][2]);
    fclose(f);
    msgs m = {""};
    snprintf(src, sizeof src,
             "import(\"%s\"); translate([10, 0, 0]) import(\"%s\", convexity = 2);", stl, off);
    csg_scene *s = scene_of(src, &m);
    cr_expect_str_empty(m.text);
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    cr_expect(fabs(lo[0]) < 1e-3 && fabs(hi[0] - 14) < 1e-3 && fabs(hi[2] - 2) < 1e-3);
    double vol = traced_volume(s, 280);
    cr_expect(fabs(vol - 48) < 0.01 * 48, "volume %g", vol);
    cr_expect(scene_contains(s, (double[3]){12, 1.5, 1}));
    cr_expect(!scene_contains(s, (double[3]){7, 1.5, 1}));
    csg_scene_free(s);
    remove(stl);
    remove(off);
    rmdir(dir);
}

Test(import, missing_and_unsupported_files_warn, .init = setup, .fini = teardown)
{
    msgs m = {""};
    scad_options o;
    memset(&o, 0, sizeof o);
    o.message = on_msg;
    o.ud = &m;
    o.services = test_services();
    scad_result r;
    cr_assert_eq(scad_eval_string("t.scad",
                                  "import(\"nowhere.stl\");\nimport(\"a.svg\");\n"
                                  "surface(\"nowhere.dat\");\nimport(\"x.abc\");",
                                  &o, &r),
                 0);
    cr_expect_str_eq(m.text,
                     "WARNING: Can't open import file 'nowhere.stl' in file t.scad, line 1\n"
                     "t.scad:2:1: warning: import() of svg files is not supported by "
                     "rayscad: 'a.svg' shows nothing\n"
                     "WARNING: The file 'nowhere.dat' couldn't be opened. in file t.scad, line 3\n"
                     "WARNING: Unsupported file format while trying to import file "
                     "'\"x.abc\"' in file t.scad, line 4\n");
    cr_expect(!r.model || csg_node_child_count(r.model) == 0);
    scad_result_free(&r);
}

/* Scene bounds are padded a little for the tracer. */
static int near(double x, double want)
{
    return fabs(x - want) < 1e-3 * (1 + fabs(want));
}

Test(resize, box_auto_and_2d, .init = setup, .fini = teardown)
{
    msgs m = {""};
    double lo[3], hi[3];
    csg_scene *s = scene_of("resize([30, 10, 5]) translate([1, 1, 1]) cube(2);", &m);
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    /* scaled about the origin: [1,3] → [15,45] in x */
    cr_expect(near(lo[0], 15) && near(hi[0], 45), "%g %g", lo[0], hi[0]);
    cr_expect(near(hi[1], 15) && near(hi[2], 7.5));
    csg_scene_free(s);
    /* auto: y follows x's scale (2), z keeps its size */
    s = scene_of("resize([8, 0, 0], auto = [0, 1, 0]) cube([4, 3, 2]);", &m);
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    cr_expect(near(hi[0], 8) && near(hi[1], 6) && near(hi[2], 2));
    csg_scene_free(s);
    /* 2D: x and y only, the preview slab stays 1 thick */
    s = scene_of("resize([10, 4]) square([5, 1]);", &m);
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    cr_expect(near(hi[0], 10) && near(hi[1], 4) && near(hi[2], 0.5));
    csg_scene_free(s);
    cr_expect_str_empty(m.text);
}

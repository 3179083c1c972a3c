/*
 * test_shapes.c — the shapes with shared data (polytope, mesh, prism,
 * revolve): their interval lists along random lines against an independent
 * point classifier, watertightness on lines through vertices and edges, and
 * reference counting.  Property tests print their seed.
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

/* ---- mesh ------------------------------------------------------------------------ */

/* OpenSCAD's manual cube: points then faces, clockwise from outside. */
static const double cube_pts[8][3] = {{0, 0, 0}, {10, 0, 0}, {10, 7, 0}, {0, 7, 0},
                                      {0, 0, 5}, {10, 0, 5}, {10, 7, 5}, {0, 7, 5}};

static const int cube_faces[] = {0, 1, 2, 3, 4, 5, 1, 0, 7, 6, 5, 4,
                                 5, 6, 2, 1, 6, 7, 3, 2, 7, 4, 0, 3};

static const int cube_start[] = {0, 4, 8, 12, 16, 20, 24};

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

static int in_disc(const double p[3], const void *ud)
{
    (void)ud;
    return p[0] * p[0] + p[1] * p[1] <= 4 && p[2] >= 0 && p[2] <= 3;
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

Test(polytope, box_planes, .init = arena_setup, .fini = arena_teardown)
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

Test(mesh, manual_cube_matches_box, .init = arena_setup, .fini = arena_teardown)
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

Test(mesh, reversed_winding_is_turned_outside_in, .init = arena_setup, .fini = arena_teardown)
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

Test(mesh, open_and_bad_input, .init = arena_setup, .fini = arena_teardown)
{
    iv_shape s;
    cr_expect_eq(iv_shape_mesh(&s, cube_pts, 8, cube_faces, cube_start, 5), 1); /* no top */
    iv_shape_release(&s);
    int bad[] = {0, 1, 9};
    int bs[] = {0, 3};
    cr_expect_eq(iv_shape_mesh(&s, cube_pts, 8, bad, bs, 1), -1);
}

/* The manual cube with the faces listed in `turn` wound the other way. */
static void cube_turned(const int *turn, int nturn, int *F)
{
    memcpy(F, cube_faces, sizeof cube_faces);
    for (int i = 0; i < nturn; i++)
        for (int j = 0; j < 4; j++)
            F[4 * turn[i] + j] = cube_faces[4 * turn[i] + 3 - j];
}

Test(polyhedron, faces_wound_inconsistently_are_turned, .init = arena_setup, .fini = arena_teardown)
{
    /* one face, then three, turned: CGAL reads the closed surface as the
     * box whatever the winding; so must we (the signed count alone made a
     * hole where the turned face is) */
    const int one[] = {2}, three[] = {0, 3, 4};
    const int *turns[] = {one, three};
    const int counts[] = {1, 3};
    double box[6] = {0, 0, 0, 10, 7, 5};
    for (int c = 0; c < 2; c++) {
        int F[24];
        cube_turned(turns[c], counts[c], F);
        iv_shape s;
        cr_assert_eq(iv_shape_polyhedron(&s, cube_pts, 8, F, cube_start, 6), 1);
        cr_expect_float_eq(iv_mesh_volume(&s), 350, 1e-9);
        cr_expect_eq(check_shape(&s, in_box, box, 12, 1000, 31 + c), 0);
        iv_shape_release(&s);
    }
    /* wound consistently: untouched */
    iv_shape s;
    cr_assert_eq(iv_shape_polyhedron(&s, cube_pts, 8, cube_faces, cube_start, 6), 0);
    iv_shape_release(&s);
}

/* A 10×7×5 box with a 4×3×1 cavity at [3,7]×[2,5]×[2,3]. */
static int in_hollow(const double p[3], const void *ud)
{
    (void)ud;
    int outer = p[0] >= 0 && p[0] <= 10 && p[1] >= 0 && p[1] <= 7 && p[2] >= 0 && p[2] <= 5;
    int cavity = p[0] > 3 && p[0] < 7 && p[1] > 2 && p[1] < 5 && p[2] > 2 && p[2] < 3;
    return outer && !cavity;
}

Test(polyhedron, a_cavity_stays_a_cavity_when_faces_are_turned, .init = arena_setup,
     .fini = arena_teardown)
{
    /* the outer box with a face turned, and the cavity's box wound as a
     * solid (outward) but for one face: the turning makes each piece
     * consistent and the inner one, inside the outer, a cavity */
    double P[16][3];
    int F[48], S[13];
    memcpy(P, cube_pts, sizeof cube_pts);
    for (int i = 0; i < 8; i++) {
        P[8 + i][0] = cube_pts[i][0] ? 7 : 3;
        P[8 + i][1] = cube_pts[i][1] ? 5 : 2;
        P[8 + i][2] = cube_pts[i][2] ? 3 : 2;
    }
    const int turn_outer[] = {1}, turn_inner[] = {4};
    cube_turned(turn_outer, 1, F);
    cube_turned(turn_inner, 1, F + 24);
    for (int j = 24; j < 48; j++)
        F[j] += 8;
    for (int f = 0; f <= 12; f++)
        S[f] = 4 * f;
    iv_shape s;
    cr_assert_eq(iv_shape_polyhedron(&s, (const double(*)[3])P, 16, F, S, 12), 1);
    cr_expect_float_eq(iv_mesh_volume(&s), 350 - 12, 1e-9);
    cr_expect_eq(check_shape(&s, in_hollow, NULL, 12, 2000, 33), 0);
    iv_shape_release(&s);
}

Test(polyhedron, t_junction_cracks_are_closed, .init = arena_setup, .fini = arena_teardown)
{
    /* the top face cut in two at x = 4 by points 8 and 9 on the long
     * edges, which the side faces do not have: their top edges are used
     * once, covered by the two halves' edges the other way */
    double P[10][3];
    memcpy(P, cube_pts, sizeof cube_pts);
    P[8][0] = 4, P[8][1] = 0, P[8][2] = 5;
    P[9][0] = 4, P[9][1] = 7, P[9][2] = 5;
    /* top (z = 5) from above is 4 5 6 7 counter-clockwise; OpenSCAD's
     * clockwise from outside is 7 6 5 4: halves 7 9 8 4 and 9 6 5 8 */
    int F[] = {0, 1, 2, 3, 7, 9, 8, 4, 9, 6, 5, 8, 5, 1, 0, 4, 5, 6, 2, 1, 6, 7, 3, 2, 7, 4, 0, 3};
    int S[] = {0, 4, 8, 12, 16, 20, 24, 28};
    /* the input's faces: 0 1 2 3 is the bottom as cube_faces has it */
    iv_shape s;
    cr_assert_eq(iv_shape_polyhedron(&s, (const double(*)[3])P, 10, F, S, 7), 2);
    double box[6] = {0, 0, 0, 10, 7, 5};
    cr_expect_eq(check_shape(&s, in_box, box, 12, 1000, 34), 0);
    iv_shape_release(&s);
}

/* The span of l holding t, or -1. */
static int span_at(const iv_list *l, double t)
{
    for (int i = 0; i < l->n; i++)
        if (l->v[i].enter.t <= t && t <= l->v[i].exit.t) return i;
    return -1;
}

Test(polyhedron, an_open_surface_is_a_sheet, .init = arena_setup, .fini = arena_teardown)
{
    /* the box without its x = 0 face (the last of six): OpenSCAD's
     * preview draws the other five, and a line meets each face it crosses
     * as a thin span */
    iv_shape s;
    cr_assert_eq(iv_shape_polyhedron(&s, cube_pts, 8, cube_faces, cube_start, 5), 3);
    iv_list l;
    cr_assert_eq(iv_list_init(&l, iv_shape_max_spans(&s), arena), 0);
    /* down: the top at z = 5 and the bottom at z = 0, nothing between */
    cr_assert_eq(iv_shape_intersect(&s, (double[3]){3, 3, 9}, (double[3]){0, 0, -1}, 0, &l), 2);
    cr_expect_float_eq(l.v[0].enter.t, 4, 1e-12);
    cr_expect_float_eq(l.v[1].enter.t, 9, 1e-12);
    cr_expect(l.v[0].exit.t - l.v[0].enter.t < 1e-6);
    cr_expect_eq(span_at(&l, 6), -1);
    /* across x: the missing face lets the line in; only x = 10 */
    l.n = 0;
    cr_assert_eq(iv_shape_intersect(&s, (double[3]){-5, 3, 2}, (double[3]){1, 0, 0}, 0, &l), 1);
    cr_expect_float_eq(l.v[0].enter.t, 15, 1e-12);
    iv_shape_release(&s);
}

Test(polyhedron, a_non_planar_quadrilateral_is_cut_as_openscad_cuts_it, .init = arena_setup,
     .fini = arena_teardown)
{
    /* openscad 2021.01 exports this face as the triangles (4,-3,1) (4,3,1)
     * (8,0,0) and (4,3,1) (4,-3,1) (0,0,0): the diagonal between the two
     * raised corners, so the surface over (4, 0) is at z = 1, not 0 */
    const double P[4][3] = {{0, 0, 0}, {4, -3, 1}, {8, 0, 0}, {4, 3, 1}};
    const int F[] = {0, 1, 2, 3}, S[] = {0, 4};
    iv_shape s;
    cr_assert_eq(iv_shape_polyhedron(&s, P, 4, F, S, 1), 3);
    iv_list l;
    cr_assert_eq(iv_list_init(&l, iv_shape_max_spans(&s), arena), 0);
    cr_assert_eq(iv_shape_intersect(&s, (double[3]){4, 0, 5}, (double[3]){0, 0, -1}, 0, &l), 1);
    cr_expect_float_eq(l.v[0].enter.t, 4, 1e-12);
    iv_shape_release(&s);
    /* the same corners in a quadrilateral whose projection has two
     * coincident corners: openscad keeps the first diagonal, (0,0,0)-(8,0,0) */
    const double Q[4][3] = {{0, 0, 0}, {4, -1, 1}, {8, 0, 0}, {4, 1, 1}};
    cr_assert_eq(iv_shape_polyhedron(&s, Q, 4, F, S, 1), 3);
    l.n = 0;
    cr_assert_eq(iv_shape_intersect(&s, (double[3]){4, 0, 5}, (double[3]){0, 0, -1}, 0, &l), 1);
    cr_expect_float_eq(l.v[0].enter.t, 5, 1e-12);
    iv_shape_release(&s);
}

static int cmp_triple(const void *a, const void *b)
{
    const int *x = a, *y = b;
    for (int k = 0; k < 3; k++)
        if (x[k] != y[k]) return x[k] - y[k];
    return 0;
}

/* The triangles of s as sorted triples, sorted, into T (room for n). */
static int sorted_triangles(const iv_shape *s, int (*T)[3], int room)
{
    int n;
    const int(*tri)[3] = iv_mesh_triangles(s, &n);
    for (int i = 0; i < n && i < room; i++) {
        int a = tri[i][0], b = tri[i][1], c = tri[i][2], x;
        if (a > b) x = a, a = b, b = x;
        if (b > c) x = b, b = c, c = x;
        if (a > b) x = a, a = b, b = x;
        T[i][0] = a, T[i][1] = b, T[i][2] = c;
    }
    qsort(T, (size_t)n, sizeof *T, cmp_triple);
    return n;
}

Test(polyhedron, a_non_planar_hexagon_is_cut_as_openscad_cuts_it, .init = arena_setup,
     .fini = arena_teardown)
{
    /* the base of the last solid of OpenSCAD's polyhedron-nonplanar-tests:
     * openscad 2021.01 exports the face [6,5,4,3,2,1] as the triangles
     * (3,1,2) (5,3,4) (3,5,1) (1,5,6) (a fan from 6 would give (6,5,4)
     * (6,4,3) (6,3,2) (6,2,1)); point 0 is no part of it, so the mesh
     * keeps points 1..6 as 0..5 */
    const double P[7][3] = {{0.5, 0.326352, 1.08481},       {0.5, 0.828269, 0.157883},
                            {1.36603, 0.992404, 0.186824},  {0.788675, 0.335865, 0.0710586},
                            {0.5, -0.484808, -0.0736482},   {0.211325, 0.335865, 0.0710586},
                            {-0.366025, 0.992404, 0.186824}};
    const int F[] = {6, 5, 4, 3, 2, 1}, S[] = {0, 6};
    iv_shape s;
    cr_assert_eq(iv_shape_polyhedron(&s, P, 7, F, S, 1), 3);
    int T[4][3], want[4][3] = {{0, 1, 2}, {0, 2, 4}, {0, 4, 5}, {2, 3, 4}};
    cr_assert_eq(sorted_triangles(&s, T, 4), 4);
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++)
            cr_expect_eq(T[i][k], want[i][k], "triangle %d: %d %d %d", i, T[i][0], T[i][1],
                         T[i][2]);
    iv_shape_release(&s);
}

Test(mesh, concave_faces_by_fans, .init = arena_setup, .fini = arena_teardown)
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

Test(prism, square_with_hole, .init = arena_setup, .fini = arena_teardown)
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

Test(prism, disc, .init = arena_setup, .fini = arena_teardown)
{
    iv_shape s;
    memset(&s, 0, sizeof s);
    s.kind = IV_SHAPE_PRISM;
    s.u.prism.r = 2;
    s.u.prism.z0 = 0;
    s.u.prism.z1 = 3;
    cr_expect_eq(check_shape(&s, in_disc, NULL, 4, 1000, 32), 0);
}

Test(revolve, triangle_profile_full_and_partial, .init = arena_setup, .fini = arena_teardown)
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

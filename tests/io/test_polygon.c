/*
 * test_polygon.c — the Clipper adapter (io/polygon.h): booleans, offsets
 * and Minkowski sums of polygon sets against areas by the shoelace formula,
 * and coordinates out of Clipper's range reported, not rounded.
 */
/*
 * test_geometry2d.c — offset(), projection(), minkowski() and text()
 * against closed forms: polygon areas by the shoelace formula for the
 * Clipper adapter (io/polygon.h), and for whole .scad sources the area of a
 * 2D result (the volume of its 1 mm preview slab) or the volume of a 3D one
 * measured by ray sampling (mesh.h), each within the stated tessellation
 * or sampling error.  Error messages are checked by their file:line:col.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/io/polygon.h"
#include "../../src/io/text.h"
#include "../../src/mesh/mesh.h"
#include "../../src/scad/scad.h"
#include "../services.h"

#define PI 3.14159265358979323846

static double shoelace(const io_paths *p)
{
    double a = 0;
    for (int i = 0; i < p->npaths; i++)
        for (int k = p->start[i]; k < p->start[i + 1]; k++) {
            int nk = k + 1 < p->start[i + 1] ? k + 1 : p->start[i];
            a += p->pts[k][0] * p->pts[nk][1] - p->pts[nk][0] * p->pts[k][1];
        }
    return a / 2;
}

static io_paths square10(double (*P)[2], int *st)
{
    double sq[4][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    memcpy(P, sq, sizeof sq);
    st[0] = 0;
    st[1] = 4;
    io_paths p = {P, st, 1};
    return p;
}

/* ---- the Clipper adapter ------------------------------------------------------------ */

Test(io_polygon, offset_delta_of_square_is_the_bigger_square)
{
    double P[4][2];
    int st[2];
    io_paths a = square10(P, st), r;
    char err[256];
    cr_assert_eq(io_polygon_offset(&a, 2, IO_JOIN_MITER, 1e6, 0, &r, err, sizeof err), 0);
    cr_assert_eq(r.npaths, 1);
    cr_assert_float_eq(shoelace(&r), 196.0, 1e-6);
    for (int i = 0; i < r.start[1]; i++) {
        cr_assert(fabs(r.pts[i][0] + 2) < 1e-9 || fabs(r.pts[i][0] - 12) < 1e-9);
        cr_assert(fabs(r.pts[i][1] + 2) < 1e-9 || fabs(r.pts[i][1] - 12) < 1e-9);
    }
    io_paths_free(&r);
}

Test(io_polygon, offset_round_of_square_has_the_rounded_area)
{
    /* s² + 4 s r + π r²; the round joins are chords within arc_tolerance
     * of the arc, which loses less than 4·(perimeter of the arcs)·tol */
    double P[4][2];
    int st[2];
    io_paths a = square10(P, st), r;
    char err[256];
    double rr = 2, tol = rr * (1 - cos(PI / 64));
    cr_assert_eq(io_polygon_offset(&a, rr, IO_JOIN_ROUND, 1e6, tol, &r, err, sizeof err), 0);
    double exact = 100 + 4 * 10 * rr + PI * rr * rr, area = shoelace(&r);
    cr_assert(area <= exact + 1e-6 && area >= exact - 2 * PI * rr * tol - 1e-3,
              "area %.6f, exact %.6f", area, exact);
    io_paths_free(&r);
}

Test(io_polygon, offset_chamfer_cuts_each_corner)
{
    /* a square join cuts each 90° corner at distance delta from the
     * vertex: a right isosceles triangle of height (√2 − 1)·delta off */
    double P[4][2];
    int st[2];
    io_paths a = square10(P, st), r;
    char err[256];
    cr_assert_eq(io_polygon_offset(&a, 2, IO_JOIN_SQUARE, 1e6, 0, &r, err, sizeof err), 0);
    double h = (sqrt(2) - 1) * 2;
    cr_assert_float_eq(shoelace(&r), 196 - 4 * h * h, 1e-3);
    io_paths_free(&r);
}

Test(io_polygon, minkowski_of_two_squares_adds_sides)
{
    double P[4][2], Q[4][2] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
    int st[2], qs[2] = {0, 4};
    io_paths a = square10(P, st), b = {Q, qs, 1}, r;
    char err[256];
    cr_assert_eq(io_polygon_minkowski(&a, &b, &r, err, sizeof err), 0);
    cr_assert_float_eq(shoelace(&r), 169.0, 1e-6);
    io_paths_free(&r);
}

Test(io_polygon, even_odd_keeps_the_hole)
{
    double P[8][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {8, 2}, {8, 8}, {2, 8}};
    int st[3] = {0, 4, 8};
    io_paths a = {P, st, 2}, none = {NULL, NULL, 0}, r;
    char err[256];
    cr_assert_eq(io_polygon_clip(IO_CLIP_UNION, &a, 1, &none, 0, &r, err, sizeof err), 0);
    cr_assert_eq(r.npaths, 2);
    cr_assert_float_eq(shoelace(&r), 100.0 - 36.0, 1e-9);
    io_paths_free(&r);
}

Test(io_polygon, out_of_range_is_an_error)
{
    double P[3][2] = {{0, 0}, {1e300, 0}, {0, 1}};
    int st[2] = {0, 3};
    io_paths a = {P, st, 1}, none = {NULL, NULL, 0}, r;
    char err[256] = "";
    cr_assert_eq(io_polygon_clip(IO_CLIP_UNION, &a, 0, &none, 0, &r, err, sizeof err), -1);
    cr_assert(strstr(err, "out of range"), "%s", err);
    /* every entry point turns the exception into the same error */
    strcpy(err, "");
    cr_assert_eq(io_polygon_offset(&a, 1, IO_JOIN_ROUND, 2, 0, &r, err, sizeof err), -1);
    cr_assert(strstr(err, "out of range"), "%s", err);
    strcpy(err, "");
    cr_assert_eq(io_polygon_offset(&none, NAN, IO_JOIN_ROUND, 2, 0, &r, err, sizeof err), -1);
    cr_assert(strstr(err, "offset out of range"), "%s", err);
    strcpy(err, "");
    cr_assert_eq(io_polygon_minkowski(&a, &a, &r, err, sizeof err), -1);
    cr_assert(strstr(err, "out of range"), "%s", err);
}

Test(io_polygon, minkowski_with_nothing_is_nothing)
{
    double P[4][2];
    int st[2];
    io_paths a = square10(P, st), none = {NULL, NULL, 0}, r;
    char err[256];
    cr_assert_eq(io_polygon_minkowski(&a, &none, &r, err, sizeof err), 0);
    cr_expect_eq(r.npaths, 0);
    cr_expect_null(r.pts);
    io_paths_free(&r);
}

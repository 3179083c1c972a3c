/*
 * test_bsp.c — booleans of polyhedra through BSP trees (src/geom/bsp.c):
 * the volumes the resulting polygons enclose (divergence theorem) against
 * closed forms for boxes and prisms in general position, touching faces,
 * disjoint operands, and the work bound.
 */
#include <criterion/criterion.h>

#include <math.h>

#include "../../src/geom/bsp.h"

#define M_PI 3.14159265358979323846

/* The six faces of the box lo..hi, counter-clockwise seen from outside. */
static void box(geom_polys *p, double x0, double y0, double z0, double x1, double y1, double z1)
{
    double c[8][3];
    for (int i = 0; i < 8; i++) {
        c[i][0] = i & 1 ? x1 : x0;
        c[i][1] = i & 2 ? y1 : y0;
        c[i][2] = i & 4 ? z1 : z0;
    }
    static const int f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int i = 0; i < 6; i++) {
        double v[4][3];
        for (int k = 0; k < 4; k++)
            for (int a = 0; a < 3; a++)
                v[k][a] = c[f[i][k]][a];
        cr_assert_eq(geom_polys_add(p, (const double(*)[3])v, 4), 0);
    }
}

/* A prism over the regular n-gon of radius r about the z axis, z0..z1,
 * turned by phi. */
static void ngon_prism(geom_polys *p, int n, double r, double phi, double z0, double z1)
{
    double top[64][3], bot[64][3];
    for (int i = 0; i < n; i++) {
        double a = phi + 2 * M_PI * i / n;
        top[i][0] = bot[n - 1 - i][0] = r * cos(a);
        top[i][1] = bot[n - 1 - i][1] = r * sin(a);
        top[i][2] = z1;
        bot[n - 1 - i][2] = z0;
    }
    cr_assert_eq(geom_polys_add(p, (const double(*)[3])top, n), 0);
    cr_assert_eq(geom_polys_add(p, (const double(*)[3])bot, n), 0);
    for (int i = 0; i < n; i++) {
        double a = phi + 2 * M_PI * i / n, b = phi + 2 * M_PI * (i + 1) / n;
        double v[4][3] = {{r * cos(a), r * sin(a), z0},
                          {r * cos(b), r * sin(b), z0},
                          {r * cos(b), r * sin(b), z1},
                          {r * cos(a), r * sin(a), z1}};
        cr_assert_eq(geom_polys_add(p, (const double(*)[3])v, 4), 0);
    }
}

/* The volume the polygons enclose: the signed tetrahedra from the origin. */
static double volume(const geom_polys *p)
{
    double v = 0;
    for (int i = 0; i < p->n; i++) {
        const double(*q)[3] = (const double(*)[3])p->v + p->start[i];
        int k = p->start[i + 1] - p->start[i];
        for (int j = 1; j + 1 < k; j++) {
            const double *a = q[0], *b = q[j], *c = q[j + 1];
            v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                  a[2] * (b[0] * c[1] - b[1] * c[0])) /
                 6;
        }
    }
    return v;
}

static double op_volume(geom_bsp_op op, const geom_polys *a, const geom_polys *b)
{
    geom_polys out = {0};
    long work = 10000000;
    cr_assert_eq(geom_bsp_boolean(op, a, b, &work, &out), 0);
    double v = volume(&out);
    geom_polys_free(&out);
    return v;
}

Test(bsp, boxes_in_general_position)
{
    geom_polys a = {0}, b = {0};
    box(&a, 0, 0, 0, 2, 3, 4);
    box(&b, 1, 1.5, -1, 5, 2.5, 3);
    cr_expect_float_eq(volume(&a), 24, 1e-12);
    double both = 1 * 1 * 3; /* x 1..2, y 1.5..2.5, z 0..3 */
    cr_expect_float_eq(op_volume(GEOM_BSP_INTERSECTION, &a, &b), both, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_UNION, &a, &b), 24 + 16 - both, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_DIFFERENCE, &a, &b), 24 - both, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_DIFFERENCE, &b, &a), 16 - both, 1e-9);
    geom_polys_free(&a);
    geom_polys_free(&b);
}

Test(bsp, shared_faces)
{
    geom_polys a = {0}, b = {0};
    box(&a, 0, 0, 0, 1, 1, 1);
    box(&b, 0, 0, 0.5, 1, 1, 2); /* four faces coplanar with a's */
    cr_expect_float_eq(op_volume(GEOM_BSP_INTERSECTION, &a, &b), 0.5, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_UNION, &a, &b), 2, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_DIFFERENCE, &a, &b), 0.5, 1e-9);
    geom_polys_free(&b);
    box(&b, 1, 0, 0, 2, 1, 1); /* touching along a face */
    cr_expect_float_eq(op_volume(GEOM_BSP_UNION, &a, &b), 2, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_INTERSECTION, &a, &b), 0, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_DIFFERENCE, &a, &b), 1, 1e-9);
    geom_polys_free(&a);
    geom_polys_free(&b);
}

Test(bsp, prisms_turned)
{
    /* two regular 24-gon prisms, one turned half a step: their
     * intersection is the 48-gon where each circle cuts the other */
    geom_polys a = {0}, b = {0};
    int n = 24;
    double r = 3, h = 2;
    ngon_prism(&a, n, r, 0, 0, h);
    ngon_prism(&b, n, r, M_PI / n, -1, 1);
    double area_n = 0.5 * n * r * r * sin(2 * M_PI / n);
    cr_expect_float_eq(volume(&a), area_n * h, 1e-9);
    /* the intersection is the regular 2n-gon on all 2n edge lines, whose
     * apothem is the n-gon's, a = r cos(pi/n): area 2n a² tan(pi/2n) */
    double apothem = r * cos(M_PI / n);
    double half_edge = apothem * tan(M_PI / (2 * n));
    double area_2n = 2 * n * apothem * half_edge;
    cr_expect_float_eq(op_volume(GEOM_BSP_INTERSECTION, &a, &b), area_2n * 1, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_UNION, &a, &b), 2 * area_n * 2 - area_2n, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_DIFFERENCE, &a, &b), area_n * 2 - area_2n, 1e-9);
    geom_polys_free(&a);
    geom_polys_free(&b);
}

Test(bsp, disjoint_and_nested)
{
    geom_polys a = {0}, b = {0};
    box(&a, 0, 0, 0, 4, 4, 4);
    box(&b, 1, 1, 1, 2, 2, 2);
    cr_expect_float_eq(op_volume(GEOM_BSP_DIFFERENCE, &a, &b), 63, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_INTERSECTION, &a, &b), 1, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_UNION, &a, &b), 64, 1e-9);
    geom_polys_free(&b);
    box(&b, 10, 10, 10, 11, 11, 11);
    cr_expect_float_eq(op_volume(GEOM_BSP_INTERSECTION, &a, &b), 0, 1e-9);
    cr_expect_float_eq(op_volume(GEOM_BSP_UNION, &a, &b), 65, 1e-9);
    geom_polys_free(&a);
    geom_polys_free(&b);
}

Test(bsp, work_bound)
{
    geom_polys a = {0}, b = {0}, out = {0};
    ngon_prism(&a, 60, 3, 0, 0, 2);
    ngon_prism(&b, 60, 3, 0.01, -1, 1);
    long work = 100;
    cr_expect_eq(geom_bsp_boolean(GEOM_BSP_INTERSECTION, &a, &b, &work, &out), GEOM_BSP_TOO_MUCH);
    cr_expect_eq(out.n, 0);
    geom_polys_free(&a);
    geom_polys_free(&b);
}

/*
 * test_minkowski.c — the geometry under minkowski() and surface() that
 * needs no evaluator (src/geom/minkowski.c, src/geom/heightmap.c): the sum
 * of two boxes against the box of summed extents, the convexity tests on
 * shapes whose answer is known, and the heightmap solid's volume against
 * its closed form (each cell's four triangles meet at the mean of the
 * corners, so the volume above the base is the cell's mean height).
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdlib.h>

#include "../../src/geom/heightmap.h"
#include "../../src/geom/minkowski.h"

static void box_points(geom_convex_set *s, const double lo[3], const double hi[3])
{
    geom_convex *q = geom_convex_set_add(s, 8);
    cr_assert(q);
    for (int i = 0; i < 8; i++, q->n++)
        for (int k = 0; k < 3; k++)
            q->p[i][k] = (i >> k) & 1 ? hi[k] : lo[k];
}

Test(geom_minkowski, box_plus_box_is_the_box_of_summed_extents)
{
    geom_convex_set a = {0}, b = {0}, out = {0};
    box_points(&a, (double[]){0, 0, 0}, (double[]){1, 2, 3});
    box_points(&b, (double[]){-1, 5, 0.5}, (double[]){4, 6, 0.75});
    cr_assert_eq(geom_minkowski_pair(&a.v[0], &b.v[0], &out), 0);
    cr_assert_eq(out.n, 1);
    const double lo[3] = {-1, 5, 0.5}, hi[3] = {5, 8, 3.75};
    cr_assert_eq(out.v[0].n, 8, "the sum has %d vertices, a box 8", out.v[0].n);
    int seen = 0;
    for (int i = 0; i < 8; i++) {
        int corner = 0;
        for (int k = 0; k < 3; k++) {
            double x = out.v[0].p[i][k];
            cr_assert(x == lo[k] || x == hi[k], "vertex %d axis %d at %g", i, k, x);
            corner |= (x == hi[k]) << k;
        }
        seen |= 1 << corner;
    }
    cr_assert_eq(seen, 0xff, "every corner once");
    geom_convex_set_free(&a);
    geom_convex_set_free(&b);
    geom_convex_set_free(&out);
}

Test(geom_minkowski, a_flat_sum_adds_nothing)
{
    geom_convex_set a = {0}, out = {0};
    geom_convex *q = geom_convex_set_add(&a, 3);
    double tri[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 3; i++, q->n++)
        for (int k = 0; k < 3; k++)
            q->p[i][k] = tri[i][k];
    cr_assert_eq(geom_minkowski_pair(&a.v[0], &a.v[0], &out), 0);
    cr_assert_eq(out.n, 0);
    geom_convex_set_free(&a);
}

Test(geom_minkowski, convexity_of_points_and_polygons)
{
    double cube[9][3];
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 3; k++)
            cube[i][k] = (i >> k) & 1;
    cube[8][0] = cube[8][1] = cube[8][2] = 0.5; /* the centre: inside the hull */
    cr_assert(geom_points_convex((const double(*)[3])cube, 8));
    cr_assert(!geom_points_convex((const double(*)[3])cube, 9));
    const double square[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const double with_collinear[5][2] = {{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}};
    const double ell[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    cr_assert(geom_polygon_convex(square, 4));
    cr_assert(geom_polygon_convex(with_collinear, 5));
    cr_assert(!geom_polygon_convex(ell, 6));
}

Test(geom_heightmap, volume_is_the_sum_of_the_cells_mean_heights)
{
    enum { W = 7, H = 5 };
    double z[W * H], lowest = INFINITY;
    srand(17);
    for (int i = 0; i < W * H; i++) {
        z[i] = (rand() % 2001 - 1000) / 100.0;
        lowest = fmin(lowest, z[i]);
    }
    geom_heightmap m = {z, W, H, fmin(0, lowest - 1)};
    double want = 0;
    for (int i = 1; i < H; i++)
        for (int j = 1; j < W; j++)
            want +=
                (z[(i - 1) * W + j - 1] + z[(i - 1) * W + j] + z[i * W + j - 1] + z[i * W + j]) /
                    4 -
                m.base;
    for (int center = 0; center < 2; center++) {
        iv_shape s;
        cr_assert_eq(geom_heightmap_mesh(&m, center, &s), 0);
        double lo[3], hi[3];
        iv_shape_bounds(&s, lo, hi);
        double x0 = center ? -(W - 1) / 2.0 : 0, y0 = center ? -(H - 1) / 2.0 : 0;
        cr_assert(lo[0] == x0 && hi[0] == x0 + W - 1 && lo[1] == y0 && hi[1] == y0 + H - 1,
                  "bounds [%g, %g] x [%g, %g]", lo[0], hi[0], lo[1], hi[1]);
        double v = fabs(iv_mesh_volume(&s));
        cr_assert(fabs(v - want) <= 1e-9 * want, "volume %.12g, want %.12g", v, want);
        iv_shape_release(&s);
    }
}

/*
 * test_pinch.c — geom_unpinch and geom_move_apart (src/geom/pinch.c) on
 * unit cubes welded where they touch: along an edge, at a corner, four
 * about one point (a 3D checkerboard), and a cube written twice.  Checked
 * against counting (the copies each pinch needs), geom_mesh_is_boundary
 * before and after, positions all apart, and the cubes' volume.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/geom/mesh_boundary.h"
#include "../../src/geom/pinch.h"
#include "../../src/intervals/vec3.h"

/* bit k of a corner's number: the high side along axis k */
static const int CUBE[12][3] = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                                {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};

typedef struct welded {
    double (*v)[3];
    int (*t)[3];
    int nv, nt;
} welded;

/* Unit cubes at the corners lo[0 .. n), their corners welded by position. */
static welded cubes(const double (*lo)[3], int n)
{
    welded w = {malloc(8 * (size_t)n * sizeof *w.v), malloc(12 * (size_t)n * sizeof *w.t), 0, 0};
    cr_assert(w.v && w.t);
    for (int c = 0; c < n; c++) {
        int id[8];
        for (int i = 0; i < 8; i++) {
            double p[3];
            for (int k = 0; k < 3; k++)
                p[k] = lo[c][k] + ((i >> k) & 1);
            id[i] = -1;
            for (int j = 0; j < w.nv && id[i] < 0; j++)
                if (memcmp(w.v[j], p, sizeof p) == 0) id[i] = j;
            if (id[i] < 0) {
                memcpy(w.v[w.nv], p, sizeof p);
                id[i] = w.nv++;
            }
        }
        for (int i = 0; i < 12; i++, w.nt++)
            for (int k = 0; k < 3; k++)
                w.t[w.nt][k] = id[CUBE[i][k]];
    }
    return w;
}

static int bounds(const welded *w)
{
    return geom_mesh_is_boundary((const double(*)[3])w->v, w->nv, (const int(*)[3])w->t, w->nt);
}

static double volume(const welded *w)
{
    double s = 0;
    for (int i = 0; i < w->nt; i++)
        s += triple3(w->v[w->t[i][0]], w->v[w->t[i][1]], w->v[w->t[i][2]]) / 6;
    return s;
}

/* Unpinched into `copies` more vertices, then moved apart by 1e-5: a
 * boundary of n cubes' volume, no two vertices at one position, each
 * within 1e-5 of a lattice point.  (At 1e-6 geom_mesh_is_boundary cannot
 * tell two faces that met at a corner in one plane apart: their
 * orientations go as the gap squared, its zero below 1e-12.) */
static void unpinch_case(const double (*lo)[3], int n, int copies)
{
    welded w = cubes(lo, n);
    int nv0 = w.nv;
    cr_expect_eq(bounds(&w), 0, "touching: no boundary as welded");
    cr_assert_eq(geom_unpinch(&w.v, &w.nv, w.t, w.nt), copies);
    cr_expect_eq(w.nv, nv0 + copies);
    cr_assert_eq(geom_move_apart(w.v, w.nv, (const int(*)[3])w.t, w.nt, 1e-5), 0);
    cr_expect_eq(bounds(&w), 1, "apart: a boundary");
    cr_expect(fabs(volume(&w) - n) < 1e-4 * n, "volume %.12g", volume(&w));
    for (int i = 0; i < w.nv; i++) {
        for (int k = 0; k < 3; k++)
            cr_expect(fabs(w.v[i][k] - round(w.v[i][k])) <= 1e-5, "off the lattice: %g", w.v[i][k]);
        for (int j = 0; j < i; j++)
            cr_expect(memcmp(w.v[i], w.v[j], sizeof w.v[i]) != 0, "vertices %d and %d", i, j);
    }
    free(w.v);
    free(w.t);
}

Test(pinch, along_an_edge)
{
    /* the edge's two ends each get a copy */
    static const double lo[2][3] = {{0, 0, 0}, {1, 1, 0}};
    unpinch_case(lo, 2, 2);
}

Test(pinch, at_a_corner)
{
    static const double lo[2][3] = {{0, 0, 0}, {1, 1, 1}};
    unpinch_case(lo, 2, 1);
}

Test(pinch, checkerboard_about_a_point)
{
    /* four cubes, each pair along an edge through (1, 1, 1): apart they
     * have 32 corners; welded, the middle one stands for 4 and each edge's
     * far end for 2 (six edges), so 32 - 3 - 6 = 23 */
    static const double lo[4][3] = {{0, 0, 0}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};
    welded w = cubes(lo, 4);
    cr_expect_eq(w.nv, 23);
    free(w.v);
    free(w.t);
    unpinch_case(lo, 4, 32 - 23);
}

Test(pinch, a_cube_twice_cannot)
{
    /* every edge has two faces in one plane on one side */
    static const double lo[2][3] = {{0, 0, 0}, {0, 0, 0}};
    welded w = cubes(lo, 2);
    cr_expect_eq(geom_unpinch(&w.v, &w.nv, w.t, w.nt), GEOM_PINCH_CANNOT);
    free(w.v);
    free(w.t);
}

Test(pinch, apart_already)
{
    /* a manifold mesh: nothing to do, nothing moved */
    static const double lo[2][3] = {{0, 0, 0}, {3, 0, 0}};
    welded w = cubes(lo, 2);
    cr_expect_eq(geom_unpinch(&w.v, &w.nv, w.t, w.nt), 0);
    cr_expect_eq(w.nv, 16);
    cr_expect_eq(geom_move_apart(w.v, w.nv, (const int(*)[3])w.t, w.nt, 1e-6), 0);
    cr_expect_eq(bounds(&w), 1);
    cr_expect_eq(volume(&w), 2);
    free(w.v);
    free(w.t);
}

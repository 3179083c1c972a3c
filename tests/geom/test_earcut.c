/*
 * test_earcut.c — geom_earcut (src/geom/earcut.c) against closed forms:
 * the triangles' areas sum to the polygon's less its holes, every one
 * turns left, every edge of a ring is used once as it runs and every
 * other edge once each way (the cut tiles the region: no overlap, no
 * gap), and rings that cross are refused.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/geom/earcut.h"

/* Cut the rings, check the tiling, return the number of triangles. */
static int cut(const double (*P)[2], const int *ring, const int *start, int nrings, double area)
{
    int(*t)[3];
    int nt = geom_earcut(P, ring, start, nrings, &t);
    if (nt < 0) return nt;
    double sum = 0;
    for (int i = 0; i < nt; i++) {
        const double *a = P[t[i][0]], *b = P[t[i][1]], *c = P[t[i][2]];
        double tw = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        cr_expect_gt(tw, 0, "triangle %d turns right or has no area", i);
        sum += tw / 2;
    }
    cr_expect_float_eq(sum, area, 1e-9 * area, "area %g, want %g", sum, area);
    /* directed edges: a ring's once as it runs, the rest once each way */
    for (int i = 0; i < nt; i++)
        for (int k = 0; k < 3; k++) {
            int a = t[i][k], b = t[i][(k + 1) % 3], same = 0, back = 0, along = 0;
            for (int j = 0; j < nt; j++)
                for (int l = 0; l < 3; l++) {
                    same += t[j][l] == a && t[j][(l + 1) % 3] == b;
                    back += t[j][l] == b && t[j][(l + 1) % 3] == a;
                }
            for (int r = 0; r < nrings; r++)
                for (int j = start[r]; j < start[r + 1]; j++) {
                    int nx = j + 1 < start[r + 1] ? j + 1 : start[r];
                    along += ring[j] == a && ring[nx] == b;
                }
            cr_expect_eq(same, 1, "edge %d-%d used %d times", a, b, same);
            cr_expect_eq(back + along, 1, "edge %d-%d: %d back, %d along a ring", a, b, back,
                         along);
        }
    free(t);
    return nt;
}

/* A comb: an outline that turns both ways, no holes. */
Test(earcut, comb)
{
    const double P[][2] = {{0, 0}, {10, 0}, {10, 5}, {8, 5}, {8, 1}, {6, 1},
                           {6, 5}, {4, 5},  {4, 1},  {2, 1}, {2, 5}, {0, 5}};
    int ring[12], start[2] = {0, 12};
    for (int i = 0; i < 12; i++)
        ring[i] = i;
    /* 50 less two slots 2 × 4 */
    cr_expect_eq(cut(P, ring, start, 1, 50 - 2 * 8), 10);
}

/* A square with two square holes side by side (clockwise), and the bridge
 * from the right one passing the left one's corner. */
Test(earcut, square_with_holes)
{
    const double P[][2] = {{0, 0}, {20, 0}, {20, 10}, {0, 10}, {3, 3},  {3, 7},
                           {7, 7}, {7, 3},  {12, 2},  {12, 8}, {17, 8}, {17, 2}};
    const int ring[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, start[] = {0, 4, 8, 12};
    /* 200 - 16 - 30; n + 2h - 2 triangles */
    cr_expect_eq(cut(P, ring, start, 3, 200 - 16 - 30), 12 + 4 - 2);
    /* the holes the other way round in the list */
    const int ring2[] = {0, 1, 2, 3, 8, 9, 10, 11, 4, 5, 6, 7};
    cr_expect_eq(cut(P, ring2, start, 3, 200 - 16 - 30), 14);
}

/* A regular 64-gon less a 64-gon hole turned half a step: a ring of thin
 * triangles between two circles. */
Test(earcut, annulus)
{
    enum { K = 64 };
    static double P[2 * K][2];
    static int ring[2 * K];
    double a_out = 0, a_in = 0;
    for (int i = 0; i < K; i++) {
        double t = 2 * 3.14159265358979323846 * i / K, u = t + 3.14159265358979323846 / K;
        P[i][0] = 10 * cos(t), P[i][1] = 10 * sin(t);
        P[K + i][0] = 9 * cos(-u), P[K + i][1] = 9 * sin(-u); /* clockwise */
        ring[i] = i, ring[K + i] = K + i;
    }
    for (int i = 0; i < K; i++) {
        int j = (i + 1) % K;
        a_out += (P[i][0] * P[j][1] - P[j][0] * P[i][1]) / 2;
        a_in -= (P[K + i][0] * P[K + j][1] - P[K + j][0] * P[K + i][1]) / 2;
    }
    const int start[] = {0, K, 2 * K};
    cr_expect_eq(cut((const double(*)[2])P, ring, start, 2, a_out - a_in), 2 * K);
}

/* An outline that crosses itself (a bow tie) has no tiling. */
Test(earcut, crossing_refused)
{
    const double P[][2] = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
    const int ring[] = {0, 1, 2, 3}, start[] = {0, 4};
    int(*t)[3];
    cr_expect_lt(geom_earcut(P, ring, start, 1, &t), 0);
}

/* A region whatever way its paths run: a square (clockwise), a hole in it
 * (counter-clockwise) and an island in the hole: 400 - 100 + 16.  As a
 * prism 3 high: volume 3 · 316 from its triangles (the divergence
 * theorem), every edge once each way. */
Test(earcut, region_and_prism)
{
    const double P[][2] = {{0, 0},   {0, 20}, {20, 20}, {20, 0}, {5, 5},   {15, 5},
                           {15, 15}, {5, 15}, {8, 8},   {12, 8}, {12, 12}, {8, 12}};
    const int start[] = {0, 4, 8, 12};
    int(*t)[3];
    int nt = geom_region_triangles(P, start, 3, &t);
    cr_assert_geq(nt, 0);
    double area = 0;
    for (int i = 0; i < nt; i++) {
        const double *a = P[t[i][0]], *b = P[t[i][1]], *c = P[t[i][2]];
        double tw = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        cr_expect_gt(tw, 0);
        area += tw / 2;
    }
    cr_expect_float_eq(area, 316, 1e-9);
    cr_expect_eq(nt, (4 + 4 + 2 - 2) + (4 - 2)); /* the square with its hole; the island */
    free(t);

    double(*v)[3];
    nt = geom_prism_mesh(P, start, 3, 1, 4, &v, &t);
    cr_assert_eq(nt, 2 * 10 + 2 * 12);
    double vol = 0;
    for (int i = 0; i < nt; i++) {
        const double *a = v[t[i][0]], *b = v[t[i][1]], *c = v[t[i][2]];
        vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                a[2] * (b[0] * c[1] - b[1] * c[0])) /
               6;
    }
    cr_expect_float_eq(vol, 3 * 316, 1e-9);
    for (int i = 0; i < nt; i++)
        for (int k = 0; k < 3; k++) {
            int a = t[i][k], b = t[i][(k + 1) % 3], same = 0, back = 0;
            for (int j = 0; j < nt; j++)
                for (int l = 0; l < 3; l++) {
                    same += t[j][l] == a && t[j][(l + 1) % 3] == b;
                    back += t[j][l] == b && t[j][(l + 1) % 3] == a;
                }
            cr_expect(same == 1 && back == 1, "edge %d-%d: %d, %d back", a, b, same, back);
        }
    free(v);
    free(t);
}

/* A plate with a 10 × 10 grid of square holes: rows and columns of them
 * share coordinates, so corners and edges lie exactly on the rays a
 * bridge would be cast along.  10000 less 100 · 16; n + 2h - 2. */
Test(earcut, grid_of_holes)
{
    static double P[4 + 400][2];
    static int ring[4 + 400], start[102];
    const double outer[4][2] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
    memcpy(P, outer, sizeof outer);
    int k = 4, r = 1;
    start[0] = 0;
    for (int i = 0; i < 10; i++)
        for (int j = 0; j < 10; j++) {
            start[r++] = k;
            const double x = 10 * i + 3, y = 10 * j + 3; /* clockwise */
            const double q[4][2] = {{x, y}, {x, y + 4}, {x + 4, y + 4}, {x + 4, y}};
            memcpy(P[k], q, sizeof q);
            k += 4;
        }
    start[r] = k;
    for (int i = 0; i < k; i++)
        ring[i] = i;
    cr_expect_eq(cut((const double(*)[2])P, ring, start, 101, 10000 - 100 * 16), 404 + 200 - 2);
}

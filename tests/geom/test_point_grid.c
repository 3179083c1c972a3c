/*
 * test_point_grid.c — geom_point_grid (src/geom/point_grid.c): every point
 * inside a box is reported, by the cells and by the fallback over all
 * points, against a brute-force scan of pseudo-random points and boxes.
 */
#include <criterion/criterion.h>

#include <stdlib.h>
#include <string.h>

#include "../../src/geom/point_grid.h"

#define N 2000

typedef struct seen {
    unsigned char hit[N];
    int calls;
} seen;

static int mark(void *ud, int i)
{
    seen *s = ud;
    s->hit[i] = 1;
    s->calls++;
    return 0;
}

static int stop_at_first(void *ud, int i)
{
    (void)ud;
    return i + 1;
}

static double rnd(unsigned *state)
{
    *state = *state * 1103515245u + 12345u;
    return (*state >> 8) / 16777216.0;
}

Test(point_grid, boxes_against_brute_force)
{
    static double p[N][3];
    unsigned st = 7;
    for (int i = 0; i < N; i++)
        for (int k = 0; k < 3; k++)
            p[i][k] = 100 * rnd(&st) - 50;
    memcpy(p[1], p[0], sizeof p[0]); /* a duplicate */
    geom_point_grid g;
    cr_assert_eq(geom_point_grid_build(&g, (const double(*)[3])p, N, 3.7), 0);
    for (int b = 0; b < 200; b++) {
        double lo[3], hi[3];
        for (int k = 0; k < 3; k++) {
            double c = 110 * rnd(&st) - 55, w = b < 100 ? 8 * rnd(&st) : 60 * rnd(&st);
            lo[k] = c - w;
            hi[k] = c + w;
        }
        for (int fallback = 0; fallback < 2; fallback++) {
            static seen s;
            memset(&s, 0, sizeof s);
            cr_assert_eq(geom_point_grid_each(&g, lo, hi, fallback ? 0 : 1000000, mark, &s), 0);
            for (int i = 0; i < N; i++) {
                int in = 1;
                for (int k = 0; k < 3; k++)
                    in &= p[i][k] >= lo[k] && p[i][k] <= hi[k];
                if (in) cr_assert(s.hit[i], "box %d: point %d missed", b, i);
            }
            if (fallback) cr_expect_eq(s.calls, N);
        }
    }
    /* a nonzero return stops the walk and is returned */
    double lo[3] = {-60, -60, -60}, hi[3] = {60, 60, 60};
    int r = geom_point_grid_each(&g, lo, hi, 1000000, stop_at_first, NULL);
    cr_expect(r >= 1 && r <= N);
    geom_point_grid_free(&g);
}

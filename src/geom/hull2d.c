/*
 * hull2d.c — the convex hull of points in the plane (hull2d.h), by
 * Andrew's monotone chain: sort by x then y, then the lower and upper
 * chains, dropping every point that does not turn left.
 */
#include "hull2d.h"

#include <stdlib.h>

static int cmp_xy(const void *a, const void *b)
{
    const double *p = a, *q = b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    return (p[1] > q[1]) - (p[1] < q[1]);
}

static double turn(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

int geom_hull2d(double (*P)[3], int n, double (*H)[2])
{
    qsort(P, (size_t)n, sizeof *P, cmp_xy);
    int k = 0;
    for (int i = 0; i < n; i++) {
        while (k >= 2 && turn(H[k - 2], H[k - 1], P[i]) <= 0)
            k--;
        H[k][0] = P[i][0];
        H[k++][1] = P[i][1];
    }
    for (int i = n - 2, lo = k + 1; i >= 0; i--) {
        while (k >= lo && turn(H[k - 2], H[k - 1], P[i]) <= 0)
            k--;
        H[k][0] = P[i][0];
        H[k++][1] = P[i][1];
    }
    return k > 1 ? k - 1 : k;
}

/*
 * trapezoid.c — a region cut into trapezoids (trapezoid.h).
 *
 * The distinct y of the vertices cut the plane into slabs; no vertex lies
 * inside a slab, so the edges that cross a slab cross it whole and keep
 * their left-to-right order within it.  Sorted by their x at the slab's
 * middle, the edges pair up (even-odd: the 1st and 2nd bound the inside,
 * the 3rd and 4th …) and each pair bounds one trapezoid.
 */
#include "trapezoid.h"

#include <stdlib.h>
#include <string.h>

typedef struct edge {
    double x0, y0, x1, y1; /* y0 < y1 */
} edge;

typedef struct cross {
    double xm, xlo, xhi; /* x at the slab's middle, bottom and top */
} cross;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static int cmp_edge(const void *a, const void *b)
{
    return cmp_double(&((const edge *)a)->y0, &((const edge *)b)->y0);
}

static int cmp_cross(const void *a, const void *b)
{
    return cmp_double(&((const cross *)a)->xm, &((const cross *)b)->xm);
}

static double x_at(const edge *e, double y)
{
    return e->x0 + (e->x1 - e->x0) * ((y - e->y0) / (e->y1 - e->y0));
}

int geom_trapezoids(const double (*P)[2], const int *start, int npaths,
                    int (*emit)(void *ud, const double (*q)[2], int k), void *ud)
{
    int npts = npaths > 0 ? start[npaths] : 0;
    if (npts < 3) return 0;
    edge *E = malloc((size_t)npts * sizeof *E);
    double *Y = malloc((size_t)npts * sizeof *Y);
    cross *C = malloc((size_t)npts * sizeof *C);
    int *active = malloc((size_t)npts * sizeof *active);
    int rc = -1, ne = 0, na = 0;
    if (!E || !Y || !C || !active) goto done;
    for (int p = 0; p < npaths; p++)
        for (int i = start[p]; i < start[p + 1]; i++) {
            int j = i + 1 < start[p + 1] ? i + 1 : start[p];
            const double *a = P[i], *b = P[j];
            if (a[1] == b[1]) continue; /* horizontal: bounds no slab */
            E[ne++] = a[1] < b[1] ? (edge){a[0], a[1], b[0], b[1]} : (edge){b[0], b[1], a[0], a[1]};
        }
    for (int i = 0; i < npts; i++)
        Y[i] = P[i][1];
    qsort(Y, (size_t)npts, sizeof *Y, cmp_double);
    qsort(E, (size_t)ne, sizeof *E, cmp_edge);
    int ny = 0;
    for (int i = 0; i < npts; i++)
        if (ny == 0 || Y[i] != Y[ny - 1]) Y[ny++] = Y[i];
    int next = 0;
    for (int s = 0; s + 1 < ny; s++) {
        double lo = Y[s], hi = Y[s + 1], mid = 0.5 * (lo + hi);
        int keep = 0;
        for (int i = 0; i < na; i++) /* edges that end at lo leave */
            if (E[active[i]].y1 > lo) active[keep++] = active[i];
        na = keep;
        while (next < ne && E[next].y0 <= lo)
            active[na++] = next++;
        int nc = 0;
        for (int i = 0; i < na; i++) {
            const edge *e = &E[active[i]];
            C[nc++] = (cross){x_at(e, mid), x_at(e, lo), x_at(e, hi)};
        }
        qsort(C, (size_t)nc, sizeof *C, cmp_cross);
        for (int i = 0; i + 1 < nc; i += 2) {
            double q[4][2] = {
                {C[i].xlo, lo}, {C[i + 1].xlo, lo}, {C[i + 1].xhi, hi}, {C[i].xhi, hi}};
            double r[4][2];
            int k = 0;
            for (int v = 0; v < 4; v++)
                if (k == 0 || q[v][0] != r[k - 1][0] || q[v][1] != r[k - 1][1])
                    memcpy(r[k++], q[v], sizeof r[0]);
            if (k > 1 && r[k - 1][0] == r[0][0] && r[k - 1][1] == r[0][1]) k--;
            if (k >= 3 && emit(ud, (const double(*)[2])r, k) != 0) goto done;
        }
    }
    rc = 0;
done:
    free(E);
    free(Y);
    free(C);
    free(active);
    return rc;
}

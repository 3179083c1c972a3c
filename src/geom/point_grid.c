/*
 * point_grid.c — points binned in a uniform grid (point_grid.h).
 */
#include "point_grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int by_cell(const void *x, const void *y)
{
    const geom_point_ref *a = x, *b = y;
    for (int k = 0; k < 3; k++)
        if (a->k[k] != b->k[k]) return a->k[k] < b->k[k] ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i);
}

/* The cell along axis k of coordinate x (clamped far past any model). */
static int64_t cell_of(const geom_point_grid *g, int k, double x)
{
    double c = floor((x - g->lo[k]) / g->cell);
    return (int64_t)fmax(-4e18, fmin(4e18, c));
}

int geom_point_grid_build(geom_point_grid *g, const double (*p)[3], int n, double cell)
{
    memset(g, 0, sizeof *g);
    g->cell = cell;
    for (int k = 0; k < 3; k++)
        g->lo[k] = n > 0 ? p[0][k] : 0;
    for (int i = 1; i < n; i++)
        for (int k = 0; k < 3; k++)
            g->lo[k] = fmin(g->lo[k], p[i][k]);
    g->r = malloc((size_t)(n > 0 ? n : 1) * sizeof *g->r);
    if (!g->r) return -1;
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++)
            g->r[i].k[k] = cell_of(g, k, p[i][k]);
        g->r[i].i = i;
    }
    qsort(g->r, (size_t)n, sizeof *g->r, by_cell);
    g->n = n;
    return 0;
}

void geom_point_grid_free(geom_point_grid *g)
{
    free(g->r);
    memset(g, 0, sizeof *g);
}

/* The first ref at or after cell (x, y, z). */
static int first_at(const geom_point_grid *g, int64_t x, int64_t y, int64_t z)
{
    geom_point_ref key = {{x, y, z}, -1};
    int lo = 0, hi = g->n;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (by_cell(&g->r[mid], &key) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

int geom_point_grid_each(const geom_point_grid *g, const double blo[3], const double bhi[3],
                         long max_columns, int (*fn)(void *ud, int i), void *ud)
{
    int64_t c0[3], c1[3];
    for (int k = 0; k < 3; k++) {
        c0[k] = cell_of(g, k, blo[k]);
        c1[k] = cell_of(g, k, bhi[k]);
    }
    double columns = ((double)(c1[0] - c0[0]) + 1) * ((double)(c1[1] - c0[1]) + 1);
    if (columns > (double)max_columns) {
        for (int i = 0; i < g->n; i++) {
            int rc = fn(ud, i);
            if (rc) return rc;
        }
        return 0;
    }
    for (int64_t x = c0[0]; x <= c1[0]; x++)
        for (int64_t y = c0[1]; y <= c1[1]; y++)
            for (int j = first_at(g, x, y, c0[2]);
                 j < g->n && g->r[j].k[0] == x && g->r[j].k[1] == y && g->r[j].k[2] <= c1[2]; j++) {
                int rc = fn(ud, g->r[j].i);
                if (rc) return rc;
            }
    return 0;
}

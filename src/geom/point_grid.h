/*
 * point_grid.h — points binned in a uniform grid (sorted by cell), to find
 * those in a box without looking at the rest.
 */
#ifndef RAYSCAD_GEOM_POINT_GRID_H
#define RAYSCAD_GEOM_POINT_GRID_H

#include <stdint.h>

typedef struct geom_point_ref {
    int64_t k[3]; /* the cell */
    int i;        /* the point */
} geom_point_ref;

typedef struct geom_point_grid {
    double lo[3], cell;
    geom_point_ref *r; /* by cell */
    int n;
} geom_point_grid;

/* Bin points p[0 .. n) in cells of side `cell` (> 0).  0, or -1 out of
 * memory. */
int geom_point_grid_build(geom_point_grid *g, const double (*p)[3], int n, double cell);
void geom_point_grid_free(geom_point_grid *g);

/* Call fn(ud, i) for every point i in a cell that box [blo, bhi] meets
 * (and so for some points outside it), until fn returns nonzero: that
 * value, or 0.  Where the box covers more than max_columns columns of
 * cells along the first two axes, fn is called for every point instead. */
int geom_point_grid_each(const geom_point_grid *g, const double blo[3], const double bhi[3],
                         long max_columns, int (*fn)(void *ud, int i), void *ud);

#endif

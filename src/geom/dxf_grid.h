/*
 * dxf_grid.h — private to src/geom: the DXF reader's point grid, its BLOCK
 * table and growable arrays (dxf_grid.c).
 */
#ifndef RAYSCAD_GEOM_DXF_GRID_H
#define RAYSCAD_GEOM_DXF_GRID_H

#include <stddef.h>
#include <stdint.h>

#define GRID 0.001 /* OpenSCAD's GRID_COARSE */

typedef struct dvec {
    double *v;
    size_t n, cap;
} dvec;

typedef struct cell {
    int64_t ix, iy;
    int head, tail; /* entries, in the order added; -1 when none */
} cell;

typedef struct entry {
    int line, next;
} entry;

typedef struct grid {
    cell *cells;
    size_t ncells, capcells;
    int *slots; /* open addressing: cell index + 1, 0 free */
    size_t nslots;
    entry *ents;
    size_t nents, capents;
} grid;

typedef struct block {
    char *name;
    double (*seg)[4];
    size_t n, cap;
} block;

typedef struct blocks {
    block *b;
    size_t n, cap;
    int *slots;
    size_t nslots;
} blocks;

/* Room for need elements of elem bytes in *p (capacity *cap), doubling:
 * 0, or -1 when out of memory (*p unchanged). */
int geom_dxf_grow(void **p, size_t *cap, size_t need, size_t elem);

/* Append x: 0, or -1 when out of memory. */
int geom_dxf_dvec_push(dvec *a, double x);

/* The cell at (ix, iy), made when missing; -1 when out of memory. */
long geom_dxf_grid_get(grid *g, int64_t ix, int64_t iy);

/* Grid2d::align: (x, y) moved onto its grid point, or onto an existing
 * neighbour's (the nearest in steps; the loop bounds follow the moving
 * ix, iy as OpenSCAD's do).  Returns the cell, -1 when out of memory. */
long geom_dxf_grid_align(grid *g, double *x, double *y);

/* List segment `line` under cell c: 0, or -1 when out of memory. */
int geom_dxf_grid_add(grid *g, long c, int line);

void geom_dxf_grid_free(grid *g);

/* The block called name, made when missing (make); NULL when absent or out
 * of memory (*oom says which). */
block *geom_dxf_block_get(blocks *t, const char *name, int make, int *oom);

void geom_dxf_blocks_free(blocks *t);

#endif

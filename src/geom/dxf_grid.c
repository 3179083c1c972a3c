/*
 * dxf_grid.c — the DXF reader's two tables (dxf_grid.h): OpenSCAD's Grid2d,
 * which snaps points to a 0.001 grid and lists the segments ending in each
 * cell, and the BLOCK definitions by name; and the growable arrays both
 * use.
 */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "dxf_grid.h"

/* ---- growable arrays ----------------------------------------------------- */

int geom_dxf_grow(void **p, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap) return 0;
    size_t c = *cap ? *cap : 16;
    while (c < need) {
        if (c > SIZE_MAX / 2 / elem) return -1;
        c *= 2;
    }
    void *q = realloc(*p, c * elem);
    if (!q) return -1;
    *p = q;
    *cap = c;
    return 0;
}

int geom_dxf_dvec_push(dvec *a, double x)
{
    if (geom_dxf_grow((void **)&a->v, &a->cap, a->n + 1, sizeof *a->v)) return -1;
    a->v[a->n++] = x;
    return 0;
}

/* ---- the grid ------------------------------------------------------------ */

static size_t hash2(int64_t x, int64_t y)
{
    uint64_t h = (uint64_t)x * 0x9E3779B97F4A7C15ull ^ ((uint64_t)y + 0x632BE59BD9B4E019ull);
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 29;
    return (size_t)h;
}

static long grid_find(const grid *g, int64_t ix, int64_t iy)
{
    if (!g->nslots) return -1;
    for (size_t s = hash2(ix, iy) & (g->nslots - 1);; s = (s + 1) & (g->nslots - 1)) {
        int c = g->slots[s];
        if (!c) return -1;
        if (g->cells[c - 1].ix == ix && g->cells[c - 1].iy == iy) return c - 1;
    }
}

/* The cell at (ix, iy), made when missing; -1 when out of memory. */
long geom_dxf_grid_get(grid *g, int64_t ix, int64_t iy)
{
    long c = grid_find(g, ix, iy);
    if (c >= 0) return c;
    if (g->ncells >= INT_MAX - 1) return -1;
    if (2 * (g->ncells + 1) > g->nslots) {
        size_t n = g->nslots ? 2 * g->nslots : 1024;
        int *s = calloc(n, sizeof *s);
        if (!s) return -1;
        for (size_t i = 0; i < g->ncells; i++) {
            size_t k = hash2(g->cells[i].ix, g->cells[i].iy) & (n - 1);
            while (s[k])
                k = (k + 1) & (n - 1);
            s[k] = (int)i + 1;
        }
        free(g->slots);
        g->slots = s;
        g->nslots = n;
    }
    if (geom_dxf_grow((void **)&g->cells, &g->capcells, g->ncells + 1, sizeof *g->cells)) return -1;
    size_t k = hash2(ix, iy) & (g->nslots - 1);
    while (g->slots[k])
        k = (k + 1) & (g->nslots - 1);
    g->slots[k] = (int)g->ncells + 1;
    g->cells[g->ncells] = (cell){ix, iy, -1, -1};
    return (long)g->ncells++;
}

/* Grid2d::align: (x, y) moved onto its grid point, or onto an existing
 * neighbour's (the nearest in steps; the loop bounds follow the moving
 * ix, iy as OpenSCAD's do).  Returns the cell, -1 when out of memory. */
long geom_dxf_grid_align(grid *g, double *x, double *y)
{
    int64_t ix = (int64_t)round(*x / GRID), iy = (int64_t)round(*y / GRID);
    if (grid_find(g, ix, iy) < 0) {
        int dist = 10;
        for (int64_t jx = ix - 1; jx <= ix + 1; jx++)
            for (int64_t jy = iy - 1; jy <= iy + 1; jy++) {
                if (grid_find(g, jx, jy) < 0) continue;
                int d = (int)(llabs(ix - jx) + llabs(iy - jy));
                if (d < dist) {
                    dist = d;
                    ix = jx;
                    iy = jy;
                }
            }
    }
    *x = (double)ix * GRID;
    *y = (double)iy * GRID;
    return geom_dxf_grid_get(g, ix, iy);
}

int geom_dxf_grid_add(grid *g, long c, int line)
{
    if (geom_dxf_grow((void **)&g->ents, &g->capents, g->nents + 1, sizeof *g->ents)) return -1;
    g->ents[g->nents] = (entry){line, -1};
    cell *p = &g->cells[c];
    if (p->tail >= 0)
        g->ents[p->tail].next = (int)g->nents;
    else
        p->head = (int)g->nents;
    p->tail = (int)g->nents++;
    return 0;
}

void geom_dxf_grid_free(grid *g)
{
    free(g->cells);
    free(g->slots);
    free(g->ents);
}

/* ---- blocks -------------------------------------------------------------- */

static size_t hash_str(const char *s)
{
    uint64_t h = 1469598103934665603ull;
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 1099511628211ull;
    return (size_t)h;
}

/* The block called name, made when missing (make); NULL when absent or out
 * of memory (*oom says which). */
block *geom_dxf_block_get(blocks *t, const char *name, int make, int *oom)
{
    if (t->nslots)
        for (size_t s = hash_str(name) & (t->nslots - 1);; s = (s + 1) & (t->nslots - 1)) {
            int k = t->slots[s];
            if (!k) break;
            if (!strcmp(t->b[k - 1].name, name)) return &t->b[k - 1];
        }
    if (!make) return NULL;
    *oom = 1;
    if (t->n >= INT_MAX - 1) return NULL;
    if (2 * (t->n + 1) > t->nslots) {
        size_t n = t->nslots ? 2 * t->nslots : 64;
        int *s = calloc(n, sizeof *s);
        if (!s) return NULL;
        for (size_t i = 0; i < t->n; i++) {
            size_t k = hash_str(t->b[i].name) & (n - 1);
            while (s[k])
                k = (k + 1) & (n - 1);
            s[k] = (int)i + 1;
        }
        free(t->slots);
        t->slots = s;
        t->nslots = n;
    }
    if (geom_dxf_grow((void **)&t->b, &t->cap, t->n + 1, sizeof *t->b)) return NULL;
    char *copy = strdup(name);
    if (!copy) return NULL;
    size_t k = hash_str(name) & (t->nslots - 1);
    while (t->slots[k])
        k = (k + 1) & (t->nslots - 1);
    t->slots[k] = (int)t->n + 1;
    t->b[t->n] = (block){copy, NULL, 0, 0};
    *oom = 0;
    return &t->b[t->n++];
}

void geom_dxf_blocks_free(blocks *t)
{
    for (size_t i = 0; i < t->n; i++) {
        free(t->b[i].name);
        free(t->b[i].seg);
    }
    free(t->b);
    free(t->slots);
}

/*
 * edges.h — a triangle mesh's directed edges, sorted so that each finds
 * its twin by binary search, and the union-find that groups triangles
 * across them (mesh_boundary.c, flat_faces.c).  Header-only.
 */
#ifndef RAYSCAD_GEOM_EDGES_H
#define RAYSCAD_GEOM_EDGES_H

#include <stdlib.h>

/* Directed edge a -> b of triangle t. */
typedef struct geom_edge {
    int a, b, t;
} geom_edge;

/* qsort order: by a, then b. */
static inline int geom_edge_cmp(const void *x, const void *y)
{
    const geom_edge *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    return (p->b > q->b) - (p->b < q->b);
}

/* The index of edge a -> b in e[0 .. ne) (sorted by geom_edge_cmp), or -1. */
static inline int geom_edge_find(const geom_edge *e, int ne, int a, int b)
{
    geom_edge key = {a, b, 0};
    const geom_edge *f = bsearch(&key, e, (size_t)ne, sizeof *e, geom_edge_cmp);
    return f ? (int)(f - e) : -1;
}

/* The root of i's set (path halving). */
static inline int geom_set_find(int *up, int i)
{
    while (up[i] != i)
        i = up[i] = up[up[i]];
    return i;
}

#endif

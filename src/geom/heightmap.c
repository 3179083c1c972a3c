/*
 * heightmap.c — surface()'s polyhedron of a heightmap (heightmap.h).
 */
#include "heightmap.h"

#include <stdlib.h>

int geom_heightmap_mesh(const geom_heightmap *m, int center, iv_shape *out)
{
    int W = m->w, H = m->h;
    double ox = center ? -(W - 1) / 2.0 : 0, oy = center ? -(H - 1) / 2.0 : 0;
    size_t cells = (size_t)(W - 1) * (size_t)(H - 1);
    /* vertices: the grid, the cell centres, the bottom ring's grid points */
    size_t nv = (size_t)W * H + cells + (size_t)W * H;
    size_t nf = 4 * cells + 2 * (size_t)(H - 1) + 2 * (size_t)(W - 1) + 1;
    size_t nidx = 12 * cells + 8 * (size_t)(H - 1) + 8 * (size_t)(W - 1) + 2 * (size_t)(W - 1) +
                  2 * (size_t)(H - 1);
    if (nv > 100000000 || nf > 100000000) return -1;
    double(*V)[3] = malloc(nv * sizeof *V);
    int *idx = malloc(nidx * sizeof *idx), *start = malloc((nf + 1) * sizeof *start);
    if (!V || !idx || !start) {
        free(V);
        free(idx);
        free(start);
        return -1;
    }
#define GRID(i, j) ((int)((size_t)(i) * (size_t)W + (size_t)(j)))
#define MID(i, j) ((int)((size_t)W * H + (size_t)((i)-1) * (size_t)(W - 1) + (size_t)((j)-1)))
#define LOW(i, j) ((int)((size_t)W * H + cells + (size_t)(i) * (size_t)W + (size_t)(j)))
    for (int i = 0; i < H; i++)
        for (int j = 0; j < W; j++) {
            double *p = V[GRID(i, j)], *q = V[LOW(i, j)];
            p[0] = q[0] = ox + j;
            p[1] = q[1] = oy + i;
            p[2] = m->z[GRID(i, j)];
            q[2] = m->base;
        }
    for (int i = 1; i < H; i++)
        for (int j = 1; j < W; j++) {
            double *p = V[MID(i, j)];
            p[0] = ox + j - 0.5;
            p[1] = oy + i - 0.5;
            p[2] = (m->z[GRID(i - 1, j - 1)] + m->z[GRID(i - 1, j)] + m->z[GRID(i, j - 1)] +
                    m->z[GRID(i, j)]) /
                   4;
        }
    size_t k = 0, f = 0;
#define FACE3(a, b, c)                                                                             \
    do {                                                                                           \
        start[f++] = (int)k;                                                                       \
        idx[k++] = (c);                                                                            \
        idx[k++] = (b);                                                                            \
        idx[k++] = (a);                                                                            \
    } while (0)
#define FACE4(a, b, c, d)                                                                          \
    do {                                                                                           \
        start[f++] = (int)k;                                                                       \
        idx[k++] = (d);                                                                            \
        idx[k++] = (c);                                                                            \
        idx[k++] = (b);                                                                            \
        idx[k++] = (a);                                                                            \
    } while (0)
    for (int i = 1; i < H; i++)
        for (int j = 1; j < W; j++) {
            int v1 = GRID(i - 1, j - 1), v2 = GRID(i - 1, j), v3 = GRID(i, j - 1), v4 = GRID(i, j),
                vx = MID(i, j);
            FACE3(v1, v2, vx);
            FACE3(v2, v4, vx);
            FACE3(v4, v3, vx);
            FACE3(v3, v1, vx);
        }
    for (int i = 1; i < H; i++) {
        FACE4(LOW(i - 1, 0), GRID(i - 1, 0), GRID(i, 0), LOW(i, 0));
        FACE4(LOW(i, W - 1), GRID(i, W - 1), GRID(i - 1, W - 1), LOW(i - 1, W - 1));
    }
    for (int j = 1; j < W; j++) {
        FACE4(LOW(0, j), GRID(0, j), GRID(0, j - 1), LOW(0, j - 1));
        FACE4(LOW(H - 1, j - 1), GRID(H - 1, j - 1), GRID(H - 1, j), LOW(H - 1, j));
    }
    /* the bottom, OpenSCAD's ring walked backwards */
    start[f++] = (int)k;
    size_t ring = k;
    for (int i = 0; i < H - 1; i++)
        idx[k++] = LOW(i, 0);
    for (int j = 0; j < W - 1; j++)
        idx[k++] = LOW(H - 1, j);
    for (int i = H - 1; i > 0; i--)
        idx[k++] = LOW(i, W - 1);
    for (int j = W - 1; j > 0; j--)
        idx[k++] = LOW(0, j);
    for (size_t a = ring, b = k - 1; a < b; a++, b--) {
        int x = idx[a];
        idx[a] = idx[b];
        idx[b] = x;
    }
    start[f] = (int)k;
#undef FACE3
#undef FACE4
#undef GRID
#undef MID
#undef LOW
    int rc = iv_shape_mesh(out, (const double(*)[3])V, (int)nv, idx, start, (int)f);
    free(V);
    free(idx);
    free(start);
    return rc < 0 ? -1 : 0;
}

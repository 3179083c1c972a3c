/*
 * trimesh.h — for the test tools (meshcmp, meshdev): a triangle mesh read
 * through OpenMesh, and the nearest of its triangles to a point, found
 * through a uniform grid of triangle boxes searched in growing shells until
 * no unseen cell can hold anything nearer (the distance is exact: the
 * closest point on a triangle, Ericson's method).  Static functions, one
 * copy in each tool.
 */
#ifndef TESTS_TOOLS_TRIMESH_H
#define TESTS_TOOLS_TRIMESH_H

#include "../../src/geom/closest.h"
#include "../../src/io/io.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    float *v;
    int32_t *t;
    int nv, nt;
    double lo[3], hi[3];
} tmesh;

static void bounds(tmesh *m)
{
    for (int c = 0; c < 3; c++) {
        m->lo[c] = INFINITY;
        m->hi[c] = -INFINITY;
    }
    for (int i = 0; i < m->nv; i++)
        for (int c = 0; c < 3; c++) {
            double x = m->v[3 * (size_t)i + c];
            m->lo[c] = fmin(m->lo[c], x);
            m->hi[c] = fmax(m->hi[c], x);
        }
}

/* ---- nearest triangle --------------------------------------------------- */

typedef struct {
    const tmesh *m;
    double org[3], cell;
    int n[3];
    int32_t *first, *items; /* CSR: triangles overlapping each cell */
    uint32_t *stamp;        /* per triangle: the last query that tested it */
    float *box;             /* per triangle: lo[3], hi[3] */
    uint32_t query;
} grid;

static int clampi(int x, int lo, int hi)
{
    return x < lo ? lo : x > hi ? hi : x;
}

static void cell_range(const grid *g, const double lo[3], const double hi[3], int a[3], int b[3])
{
    for (int c = 0; c < 3; c++) {
        a[c] = clampi((int)floor((lo[c] - g->org[c]) / g->cell), 0, g->n[c] - 1);
        b[c] = clampi((int)floor((hi[c] - g->org[c]) / g->cell), 0, g->n[c] - 1);
    }
}

static void tri_box(const tmesh *m, int q, double lo[3], double hi[3])
{
    for (int c = 0; c < 3; c++) {
        lo[c] = INFINITY;
        hi[c] = -INFINITY;
    }
    for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++) {
            double x = m->v[3 * (size_t)m->t[3 * q + k] + c];
            lo[c] = fmin(lo[c], x);
            hi[c] = fmax(hi[c], x);
        }
}

static int grid_build(grid *g, const tmesh *m, double cell)
{
    memset(g, 0, sizeof *g);
    g->m = m;
    g->cell = cell;
    size_t cells = 1;
    for (int c = 0; c < 3; c++) {
        g->org[c] = m->lo[c] - cell;
        g->n[c] = (int)ceil((m->hi[c] - g->org[c]) / cell) + 1;
        cells *= (size_t)g->n[c];
    }
    g->first = calloc(cells + 1, sizeof *g->first);
    g->stamp = calloc((size_t)m->nt + 1, sizeof *g->stamp);
    g->box = malloc(((size_t)m->nt + 1) * 6 * sizeof *g->box);
    if (!g->first || !g->stamp || !g->box) return -1;
    for (int q = 0; q < m->nt; q++) {
        double lo[3], hi[3];
        tri_box(m, q, lo, hi);
        for (int c = 0; c < 3; c++) {
            g->box[6 * (size_t)q + c] = (float)lo[c];
            g->box[6 * (size_t)q + 3 + c] = (float)hi[c];
        }
    }
    for (int pass = 0; pass < 2; pass++) {
        for (int q = 0; q < m->nt; q++) {
            double lo[3], hi[3];
            int a[3], b[3];
            tri_box(m, q, lo, hi);
            cell_range(g, lo, hi, a, b);
            for (int z = a[2]; z <= b[2]; z++)
                for (int y = a[1]; y <= b[1]; y++)
                    for (int x = a[0]; x <= b[0]; x++) {
                        size_t c = ((size_t)z * g->n[1] + y) * g->n[0] + x;
                        if (pass == 0)
                            g->first[c + 1]++;
                        else
                            g->items[g->first[c]++] = q;
                    }
        }
        if (pass == 0) {
            for (size_t c = 0; c < cells; c++)
                g->first[c + 1] += g->first[c];
            g->items = malloc(((size_t)g->first[cells] + 1) * sizeof *g->items);
            if (!g->items) return -1;
        } else { /* the fill advanced each start to the next one's: shift back */
            for (size_t c = cells; c > 0; c--)
                g->first[c] = g->first[c - 1];
            g->first[0] = 0;
        }
    }
    return 0;
}

static void grid_free(grid *g)
{
    free(g->first);
    free(g->items);
    free(g->stamp);
    free(g->box);
}

static void vertex(const tmesh *m, int32_t i, double out[3])
{
    for (int c = 0; c < 3; c++)
        out[c] = m->v[3 * (size_t)i + c];
}

/* Distance from p to the nearest triangle in g. */
static double grid_nearest(grid *g, const double p[3])
{
    g->query++;
    int home[3];
    for (int c = 0; c < 3; c++)
        home[c] = (int)floor((p[c] - g->org[c]) / g->cell);
    double best2 = INFINITY;
    int rmax = g->n[0] + g->n[1] + g->n[2] + 2 * abs(home[0]) + 2 * abs(home[1]) + 2 * abs(home[2]);
    for (int r = 0; r <= rmax; r++) {
        for (int z = home[2] - r; z <= home[2] + r; z++) {
            if (z < 0 || z >= g->n[2]) continue;
            for (int y = home[1] - r; y <= home[1] + r; y++) {
                if (y < 0 || y >= g->n[1]) continue;
                int shell_yz = abs(z - home[2]) == r || abs(y - home[1]) == r;
                for (int x = home[0] - r; x <= home[0] + r; x += shell_yz ? 1 : 2 * r) {
                    if (x >= 0 && x < g->n[0]) {
                        size_t c = ((size_t)z * g->n[1] + y) * g->n[0] + x;
                        for (int32_t k = g->first[c]; k < g->first[c + 1]; k++) {
                            int32_t q = g->items[k];
                            if (g->stamp[q] == g->query) continue;
                            g->stamp[q] = g->query;
                            /* No nearer than the triangle's box. */
                            const float *bx = g->box + 6 * (size_t)q;
                            double bd2 = 0;
                            for (int c3 = 0; c3 < 3; c3++) {
                                double e = fmax(fmax(bx[c3] - p[c3], p[c3] - bx[3 + c3]), 0);
                                bd2 += e * e;
                            }
                            if (bd2 >= best2) continue;
                            double a[3], b[3], cc[3];
                            vertex(g->m, g->m->t[3 * q], a);
                            vertex(g->m, g->m->t[3 * q + 1], b);
                            vertex(g->m, g->m->t[3 * q + 2], cc);
                            double d2 = geom_triangle_dist2(p, a, b, cc);
                            if (d2 < best2) best2 = d2;
                        }
                    }
                    if (r == 0) break;
                }
            }
        }
        /* Every cell not searched yet lies outside the block of cells
         * home ± r, so at least as far from p as the block's nearest wall. */
        double wall = INFINITY;
        for (int c = 0; c < 3; c++) {
            double x = p[c] - g->org[c];
            wall = fmin(wall, fmin(x - (home[c] - r) * g->cell, (home[c] + r + 1) * g->cell - x));
        }
        if (best2 <= wall * wall) break;
    }
    return sqrt(best2);
}

/* Keep distance d, found at p, when it is the largest yet. */
static void keep_worst(double d, const double p[3], double *worst, double where[3])
{
    if (d > *worst) {
        *worst = d;
        memcpy(where, p, 3 * sizeof *p);
    }
}

/* Read path into m (and its bounds); 0, or -1 with a message on stderr. */
static int load(const char *path, tmesh *m)
{
    char err[512];
    memset(m, 0, sizeof *m);
    if (io_mesh_read(path, &m->v, &m->nv, &m->t, &m->nt, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    if (m->nt == 0) {
        fprintf(stderr, "%s: no triangles\n", path);
        return -1;
    }
    bounds(m);
    return 0;
}

#endif

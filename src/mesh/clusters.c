/*
 * clusters.c — a part of a model that is not plane-faced as a whole split
 * into clusters of its top-level operands, those that are meshed exactly
 * (mesh_polyhedral_clusters).
 *
 * A part is the operands whose grids would meet (pieces.c), or the whole
 * model where its parts are too many for grids of their own; one curved
 * primitive, or one mesh that does not bound its solid, and the whole part
 * was contoured.  Here its operands are gathered into clusters whose boxes
 * lie within MESH_CLUSTER_PAD cells of one another, and each cluster whose
 * booleans come out exact (polyhedral.c) is written so: its crossings move
 * to a grid that is not contoured, the rest's to one that is.  Clusters
 * further apart than the contour's reach (its probes along a vertex's
 * normal go a cell, its cells pad the box by three) do not see each other,
 * so each interval of a ray lies in one cluster: the one whose operands'
 * boxes hold its entry.  The check against the grid (2 % of the volume) is
 * made per cluster, from its intervals alone.
 */
#include "../geom/edges.h"
#include "dexels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_OPERANDS 256
#define MESH_CLUSTER_PAD 4.0 /* cells between clusters' boxes */

typedef struct operand {
    int32_t node;
    double lo[3], hi[3];
    int cluster;
} operand;

typedef struct gather {
    const double *lo, *hi;
    operand *op;
    int n, over;
} gather;

static int collect(void *ud, int32_t i, const csg_scene_node_info *f)
{
    gather *g = ud;
    for (int a = 0; a < 3; a++) {
        if (!isfinite(f->lo[a]) || !isfinite(f->hi[a])) g->over = 1;
        if (f->lo[a] > g->hi[a] || f->hi[a] < g->lo[a]) return g->over; /* another part's */
    }
    if (g->n == MAX_OPERANDS) g->over = 1;
    if (g->over) return 1;
    operand *o = &g->op[g->n++];
    o->node = i;
    memcpy(o->lo, f->lo, sizeof o->lo);
    memcpy(o->hi, f->hi, sizeof o->hi);
    return 0;
}

/* The operands' clusters (op[].cluster, 0 .. count - 1): boxes within pad
 * of one another, transitively.  Their count. */
static int cluster(operand *op, int n, double pad)
{
    int up[MAX_OPERANDS], id[MAX_OPERANDS], count = 0;
    for (int i = 0; i < n; i++)
        up[i] = i;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            int apart = 0;
            for (int a = 0; a < 3; a++)
                apart |= op[i].lo[a] > op[j].hi[a] + pad || op[j].lo[a] > op[i].hi[a] + pad;
            if (!apart) up[geom_set_find(up, i)] = geom_set_find(up, j);
        }
    for (int i = 0; i < n; i++)
        id[i] = -1;
    for (int i = 0; i < n; i++) {
        int r = geom_set_find(up, i);
        if (id[r] < 0) id[r] = count++;
        op[i].cluster = id[r];
    }
    return count;
}

/* The cluster whose operands' boxes (grown by slack) hold p, or -1. */
static int cluster_at(const operand *op, int n, const double p[3], double slack)
{
    for (int i = 0; i < n; i++) {
        int in = 1;
        for (int a = 0; a < 3 && in; a++)
            in = p[a] >= op[i].lo[a] - slack && p[a] <= op[i].hi[a] + slack;
        if (in) return op[i].cluster;
    }
    return -1;
}

/* The rays of family a of d. */
static size_t rays_of(const mesh_dexels *d, int a)
{
    int u, v;
    mesh_axes_other(a, &u, &v);
    return ((size_t)d->n[u] + 1) * ((size_t)d->n[v] + 1);
}

/* Each interval of d's rays (family a, hits k and k + 1) labelled with the
 * cluster of its entry, which[a][k / 2], and each cluster's Σ lengths over
 * the three families in volume[]: 0, 1 where an entry lies in no cluster's
 * boxes, or -1 out of memory. */
static int label(const mesh_dexels *d, const operand *op, int n, int16_t *which[3], double *volume)
{
    for (int a = 0; a < 3; a++) {
        which[a] = malloc((d->nhit[a] / 2 + 1) * sizeof *which[a]);
        if (!which[a]) return -1;
        int u, v;
        mesh_axes_other(a, &u, &v);
        size_t rowlen = (size_t)d->n[u] + 1, rays = rays_of(d, a);
        for (size_t r = 0; r < rays; r++)
            for (size_t k = d->off[a][r]; k + 1 < d->off[a][r + 1]; k += 2) {
                double p[3];
                p[a] = d->org[a] + d->hit[a][k].t;
                p[u] = d->org[u] + (double)(r % rowlen) * d->h;
                p[v] = d->org[v] + (double)(r / rowlen) * d->h;
                int cl = cluster_at(op, n, p, d->h);
                if (cl < 0) return 1;
                which[a][k / 2] = (int16_t)cl;
                volume[cl] += d->hit[a][k + 1].t - d->hit[a][k].t;
            }
    }
    return 0;
}

/* Grid r: d's layout, patches and palette, no crossings yet; 0 or -1. */
static int twin_grid(const mesh_dexels *d, mesh_dexels *r)
{
    memset(r, 0, sizeof *r);
    r->h = d->h;
    memcpy(r->org, d->org, sizeof r->org);
    memcpy(r->n, d->n, sizeof r->n);
    r->scene = d->scene;
    r->root = d->root;
    r->exact = -1;
    r->patch_cap = d->patch_cap;
    r->patch_key = malloc((d->patch_cap ? d->patch_cap : 1) * sizeof *r->patch_key);
    r->patch_curved = malloc(d->patch_cap ? d->patch_cap : 1);
    if (!r->patch_key || !r->patch_curved) return -1;
    memcpy(r->patch_key, d->patch_key, d->patch_cap * sizeof *r->patch_key);
    memcpy(r->patch_curved, d->patch_curved, d->patch_cap);
    return mesh_palette_build(d->scene, d->root, &r->pal);
}

/* d's crossings parted by their intervals' labels: those of exact clusters
 * stay in d, the rest go to the new grid *rest.  0 or -1 (d unchanged). */
static int part_hits(mesh_dexels *d, int16_t *const which[3], const uint8_t *exact,
                     mesh_dexels **rest)
{
    mesh_dexels *r = malloc(sizeof *r);
    size_t *off[2][3] = {{NULL}};
    mesh_hit *hit[2][3] = {{NULL}};
    int rc = r ? twin_grid(d, r) : -1;
    for (int a = 0; a < 3 && rc == 0; a++) {
        size_t rays = rays_of(d, a);
        for (int side = 0; side < 2 && rc == 0; side++)
            if (!(off[side][a] = calloc(rays + 1, sizeof(size_t)))) rc = -1;
        for (size_t ray = 0; rc == 0 && ray < rays; ray++)
            for (size_t k = d->off[a][ray]; k + 1 < d->off[a][ray + 1]; k += 2)
                off[exact[which[a][k / 2]]][a][ray + 1] += 2;
        for (int side = 0; side < 2 && rc == 0; side++) {
            size_t *c = off[side][a];
            for (size_t i = 0; i < rays; i++)
                c[i + 1] += c[i];
            if (!(hit[side][a] = malloc((c[rays] ? c[rays] : 1) * sizeof(mesh_hit)))) rc = -1;
        }
        size_t n[2] = {0, 0}; /* each side's next free place: rays in order */
        for (size_t ray = 0; rc == 0 && ray < rays; ray++)
            for (size_t k = d->off[a][ray]; k + 1 < d->off[a][ray + 1]; k += 2) {
                int side = exact[which[a][k / 2]];
                memcpy(&hit[side][a][n[side]], &d->hit[a][k], 2 * sizeof(mesh_hit));
                n[side] += 2;
            }
    }
    for (int a = 0; a < 3; a++) {
        if (rc == 0) {
            size_t rays = rays_of(d, a);
            free(d->off[a]);
            free(d->hit[a]);
            d->off[a] = off[1][a];
            d->hit[a] = hit[1][a];
            d->nhit[a] = off[1][a][rays];
            r->off[a] = off[0][a];
            r->hit[a] = hit[0][a];
            r->nhit[a] = off[0][a][rays];
        } else {
            for (int side = 0; side < 2; side++) {
                free(off[side][a]);
                free(hit[side][a]);
            }
        }
    }
    if (rc != 0) {
        mesh_dexels_free(r);
        r = NULL;
    }
    *rest = r;
    return rc;
}

/* Append q's corners, triangles and colours to p; 0 or -1. */
static int join(mesh_polyhedron *p, const mesh_polyhedron *q)
{
    double(*v)[3] = realloc(p->v, (size_t)(p->nv + q->nv) * sizeof *v);
    if (v) p->v = v;
    int(*t)[3] = v ? realloc(p->t, (size_t)(p->nt + q->nt) * sizeof *t) : NULL;
    if (t) p->t = t;
    uint16_t *c = t ? realloc(p->color, (size_t)(p->nt + q->nt) * sizeof *c) : NULL;
    if (!c) return -1;
    p->color = c;
    memcpy(p->v + p->nv, q->v, (size_t)q->nv * sizeof *v);
    for (int i = 0; i < q->nt; i++) {
        for (int k = 0; k < 3; k++)
            p->t[p->nt + i][k] = q->t[i][k] + p->nv;
        p->color[p->nt + i] = q->color[i];
    }
    p->nv += q->nv;
    p->nt += q->nt;
    return 0;
}

int mesh_polyhedral_clusters(mesh_dexels *d, const double lo[3], const double hi[3])
{
    int32_t root = csg_scene_root_node(d->scene, d->root);
    if (root < 0 || !d->off[0]) return 0;
    operand op[MAX_OPERANDS];
    gather g = {.lo = lo, .hi = hi, .op = op};
    mesh_top_operands(d->scene, root, collect, &g);
    if (g.over || g.n < 2) return 0;
    int n = g.n, nc = cluster(op, n, MESH_CLUSTER_PAD * d->h), rc = 0, any = 0;
    if (nc < 2) return 0;
    double *volume = calloc((size_t)nc, sizeof *volume);
    uint8_t *exact = calloc((size_t)nc, 1);
    int32_t *nodes = malloc((size_t)n * sizeof *nodes);
    mesh_polyhedron all = {0}, *shell = calloc((size_t)nc, sizeof *shell);
    int16_t *which[3] = {NULL, NULL, NULL};
    if (!volume || !exact || !nodes || !shell) rc = -1;
    /* the clusters' booleans first (a curved one fails at once), then
     * their volumes on the grid, where one came out */
    for (int cl = 0; cl < nc && rc == 0; cl++) {
        int m = 0;
        for (int i = 0; i < n; i++)
            if (op[i].cluster == cl) nodes[m++] = op[i].node;
        int r = mesh_polyhedral_of(d, lo, hi, nodes, m, &shell[cl]);
        if (r < 0) rc = -1;
        exact[cl] = r == 1;
        any |= r == 1;
    }
    int labelled = rc == 0 && any ? label(d, op, n, which, volume) : 0;
    if (labelled < 0) rc = -1;
    if (labelled != 0) /* (1: an interval the clusters do not tell: leave the part whole) */
        memset(exact, 0, (size_t)nc);
    for (int cl = 0; cl < nc && rc == 0 && any; cl++) {
        if (!exact[cl]) continue;
        exact[cl] = mesh_polyhedral_agrees(&shell[cl], volume[cl] * d->h * d->h / 3, d->h);
        if (exact[cl] && join(&all, &shell[cl]) != 0) rc = -1;
    }
    any = 0;
    for (int cl = 0; cl < nc && rc == 0; cl++)
        any |= exact[cl];
    mesh_dexels *rest = NULL;
    if (rc == 0 && any && part_hits(d, which, exact, &rest) != 0) rc = -1;
    if (rc == 0 && any) {
        mesh_polyhedron_free(&d->poly);
        d->poly = all;
        d->exact = MESH_POLYHEDRAL;
        rest->next = d->next;
        d->next = rest;
        rc = 1;
    } else {
        mesh_polyhedron_free(&all);
    }
    for (int cl = 0; shell && cl < nc; cl++)
        mesh_polyhedron_free(&shell[cl]);
    free(shell);
    for (int a = 0; a < 3; a++)
        free(which[a]);
    free(volume);
    free(exact);
    free(nodes);
    return rc;
}

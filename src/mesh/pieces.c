/*
 * pieces.c — the far-apart parts of a model, each to be sampled on a grid
 * of its own.
 *
 * A grid's spacing follows the longest side of what it covers, so one grid
 * over a small part and another far away would sample the small part
 * coarsely (a 28 mm ring 900 mm from a 4 mm cube: 7 mm cells, 4 across the
 * ring's tube) and cast most of its rays through empty space.  The operands
 * of the top-level unions (an n-ary union in the committed tree, nested
 * unions flattened) are gathered by their bounds; boxes whose grids could
 * reach each other are merged until no two meet.  Since every grid covers
 * only its own box (plus 3 cells, see dexels.c), the rays of one group never
 * see another's surface, and the meshes of the groups are disjoint.
 */
#include "dexels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* More operands than this are sampled on one grid: merging is quadratic, and
 * a model of thousands of parts is rarely spread out. */
#define PIECES_MAX 256
/* How far a grid reaches past its box, in cells: the origin lies 1.5 cells
 * below it and the last node up to 2.5 cells above. */
#define PIECES_PAD 3.0

typedef struct gather {
    mesh_piece *p;
    int n;
    int over; /* more than PIECES_MAX, or an unbounded operand */
} gather;

int mesh_top_operands(const csg_scene *s, int32_t i, mesh_operand_fn fn, void *ud)
{
    csg_scene_node_info f;
    csg_scene_node_get(s, i, &f);
    if (f.is_leaf || f.op != CSG_OP_UNION) return fn(ud, i, &f);
    csg_scene_node_info c;
    for (int32_t k = i + 1; k < f.end; k = c.end) {
        csg_scene_node_get(s, k, &c);
        int rc = mesh_top_operands(s, k, fn, ud);
        if (rc) return rc;
    }
    return 0;
}

static int collect(void *ud, int32_t i, const csg_scene_node_info *f)
{
    gather *g = ud;
    (void)i;
    for (int a = 0; a < 3; a++)
        if (!isfinite(f->lo[a]) || !isfinite(f->hi[a])) g->over = 1;
    if (g->n == PIECES_MAX) g->over = 1;
    if (g->over) return 1;
    memcpy(g->p[g->n].lo, f->lo, sizeof f->lo);
    memcpy(g->p[g->n].hi, f->hi, sizeof f->hi);
    g->p[g->n].prim = f->is_leaf ? f->prim : -1;
    g->n++;
    return 0;
}

double mesh_piece_longest(const mesh_piece *p)
{
    double l = 0;
    for (int a = 0; a < 3; a++)
        l = fmax(l, p->hi[a] - p->lo[a]);
    return l;
}

/* The spacing a piece's own grid gets. */
static double piece_h(const mesh_piece *p, double h, int cells)
{
    return h > 0 ? h : mesh_piece_longest(p) / cells;
}

/* 1 when grids of spacings hp over p and hq over q would meet. */
static int meet(const mesh_piece *p, const mesh_piece *q, double hp, double hq)
{
    double pad = PIECES_PAD * (hp + hq);
    for (int a = 0; a < 3; a++)
        if (p->lo[a] > q->hi[a] + pad || q->lo[a] > p->hi[a] + pad) return 0;
    return 1;
}

int mesh_pieces(const csg_scene *s, int root, double h, int cells, mesh_piece **out)
{
    *out = NULL;
    int32_t r = csg_scene_root_node(s, root);
    if (r < 0) return 0;
    gather g = {.p = malloc(PIECES_MAX * sizeof *g.p)};
    if (!g.p) return -1;
    mesh_top_operands(s, r, collect, &g);
    if (g.over || g.n == 0) {
        g.n = 1;
        csg_scene_bounds(s, root, g.p[0].lo, g.p[0].hi);
        g.p[0].prim = -1;
    }
    /* Merge any two pieces whose grids meet, until none do. */
    for (int merged = 1; merged;) {
        merged = 0;
        for (int i = 0; i < g.n; i++)
            for (int j = i + 1; j < g.n; j++) {
                if (!meet(&g.p[i], &g.p[j], piece_h(&g.p[i], h, cells), piece_h(&g.p[j], h, cells)))
                    continue;
                for (int a = 0; a < 3; a++) {
                    g.p[i].lo[a] = fmin(g.p[i].lo[a], g.p[j].lo[a]);
                    g.p[i].hi[a] = fmax(g.p[i].hi[a], g.p[j].hi[a]);
                }
                g.p[i].prim = -1;
                g.p[j--] = g.p[--g.n];
                merged = 1;
            }
    }
    *out = g.p;
    return g.n;
}

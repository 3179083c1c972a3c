/*
 * palette.c — the colours a mesh carries: the distinct color() values of the
 * leaves under a root, numbered from 1 (0: no colour given), and which
 * number each primitive gets.  The dexel casting tags every crossing with
 * its primitive's number and the contour gives each triangle the number of
 * the crossing it is drawn from.
 */
#include "dexels.h"

#include <stdlib.h>
#include <string.h>

void mesh_palette_free(mesh_palette *p)
{
    free(p->rgba);
    free(p->of_prim);
    memset(p, 0, sizeof *p);
}

int mesh_palette_build(const csg_scene *s, int root, mesh_palette *p)
{
    memset(p, 0, sizeof *p);
    int32_t first = csg_scene_root_node(s, root);
    if (first < 0) return 0;
    csg_scene_node_info info;
    csg_scene_node_get(s, first, &info);
    int32_t end = info.end, nprim = 0;
    for (int32_t i = first; i < end; i++) {
        csg_scene_node_get(s, i, &info);
        if (info.is_leaf && info.prim >= nprim) nprim = info.prim + 1;
    }
    p->of_prim = calloc(nprim ? (size_t)nprim : 1, sizeof *p->of_prim);
    if (!p->of_prim) return -1;
    p->nprim = nprim;
    int cap = 0;
    for (int32_t i = first; i < end; i++) {
        csg_scene_node_get(s, i, &info);
        if (!info.is_leaf) continue;
        const csg_material *m = csg_scene_material(s, info.prim);
        if (!m->has_color) continue;
        int k = 0;
        while (k < p->n && memcmp(p->rgba[k], m->rgba, sizeof m->rgba))
            k++;
        if (k == p->n) {
            if (p->n == MESH_PALETTE_MAX) continue; /* more colours than a tag holds: none */
            if (p->n == cap) {
                cap = cap ? 2 * cap : 8;
                float(*q)[4] = realloc(p->rgba, (size_t)cap * sizeof *q);
                if (!q) {
                    mesh_palette_free(p);
                    return -1;
                }
                p->rgba = q;
            }
            memcpy(p->rgba[p->n++], m->rgba, sizeof m->rgba);
        }
        p->of_prim[info.prim] = (uint16_t)(k + 1);
    }
    return 0;
}

uint16_t mesh_palette_of(const mesh_palette *p, int32_t prim)
{
    return prim >= 0 && prim < p->nprim ? p->of_prim[prim] : 0;
}

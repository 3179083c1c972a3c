/*
 * inspect.c — read-only access to a committed scene's flat tree, for
 * exporters (render/pov_export.c).  Nothing here changes the scene, so it is
 * as thread-safe as csg_trace.
 */
#include "csg_internal.h"

#include <string.h>

int csg_scene_node_count(const csg_scene *s)
{
    return s->nnodes;
}

int32_t csg_scene_root_node(const csg_scene *s, int r)
{
    if (r < 0 || r >= s->nroots) return -1;
    return s->roots[r];
}

void csg_scene_node_get(const csg_scene *s, int32_t i, csg_scene_node_info *out)
{
    const csg_fnode *f = &s->nodes[i];
    out->is_leaf = f->op == FNODE_LEAF;
    out->op = out->is_leaf ? CSG_OP_UNION : (csg_op)f->op;
    out->prim = f->prim;
    out->end = f->next;
    memcpy(out->lo, f->lo, sizeof out->lo);
    memcpy(out->hi, f->hi, sizeof out->hi);
}

const iv_shape *csg_scene_prim_shape(const csg_scene *s, int32_t prim)
{
    return &s->prims[prim].shape;
}

void csg_scene_prim_transform(const csg_scene *s, int32_t prim, csg_affine out)
{
    /* Commit inverted a non-singular transform, so this inverse exists. */
    if (csg_affine_invert(s->prims[prim].object_from_world, out) != 0)
        memcpy(out, csg_affine_identity, sizeof(csg_affine));
}

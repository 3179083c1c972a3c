/*
 * csg_internal.h — the builder's node and the committed scene's arrays,
 * shared by node.c, scene.c and trace.c only.
 */
#ifndef RAYSCAD_CSG_INTERNAL_H
#define RAYSCAD_CSG_INTERNAL_H

#include "csg.h"

/* Builder node.  A leaf has kids == NULL and nkids == 0.  `link` is scratch
 * for the non-recursive walks (free, commit) and means nothing between
 * calls. */
struct csg_node {
    int is_leaf;
    csg_op op;
    iv_shape shape;
    csg_affine world_from_object;
    csg_material material;
    csg_node **kids;
    int nkids, cap;
    csg_node *link;
    /* Filled by commit. */
    int visit;                    /* children already simplified */
    double object_from_world[12]; /* leaf */
    double lo[3], hi[3];          /* world bounds, padded outward */
    int size;                     /* nodes in the subtree, itself included */
    int leaves;                   /* leaves in the subtree */
    int depth;                    /* 1 for a leaf */
};

/* Flattened node.  Pre-order: an op node's first child is at index + 1 and
 * each child's sibling at that child's `next`; `next` of a node is the index
 * just past its subtree.  64 bytes: one cache line. */
enum { FNODE_LEAF = 3 }; /* `op` of a leaf; ops use their csg_op value */

typedef struct csg_fnode {
    double lo[3], hi[3]; /* world AABB, padded outward; may be infinite */
    int32_t next;
    int32_t prim; /* leaf: primitive index; op: -1 */
    uint8_t op;   /* csg_op, or FNODE_LEAF */
} csg_fnode;

/* What the per-ray loop reads for a primitive. */
typedef struct csg_prim {
    double object_from_world[12];
    iv_shape shape;
} csg_prim;

/* What only shading reads. */
typedef struct csg_prim_cold {
    double normal_from_object[9]; /* row-major, the inverse transpose of
                                     world_from_object's linear part */
    csg_material material;
} csg_prim_cold;

struct csg_scene {
    csg_fnode *nodes;
    int nnodes;
    csg_prim *prims;
    csg_prim_cold *cold;
    int nprims;
    int32_t *roots; /* node index of each root, or -1 when empty */
    int nroots;
    int max_depth; /* deepest root, in nodes; sizes the trace's stack */
    int cull;      /* 1: test node bounds (0 only in tests, via csg_scene_set_cull) */
};

/* Testing hook: turn bounds culling off (0) or on (1) to check that culling
 * never changes a result.  Not thread-safe against concurrent traces. */
void csg_scene_set_cull(csg_scene *s, int on);

#endif

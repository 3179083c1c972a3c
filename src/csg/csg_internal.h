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
    int whole; /* framed as one piece (csg_node_frame_whole) */
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
    int32_t prim;  /* leaf: primitive index; op: -1 */
    int32_t wide;  /* union: its first csg_wide record; other nodes: -1 */
    uint8_t op;    /* csg_op, or FNODE_LEAF */
    uint8_t whole; /* op: framed as one piece (csg_node_frame_whole) */
} csg_fnode;

/* A union's operands, four to a record, as csg_trace_first reads them: the
 * boxes axis by axis, so that one ray tests four at once, and what a popped
 * operand needs without reading its csg_fnode (`ref`: a union's first
 * record, -2 - prim for a leaf, -1 for an intersection or a difference).  A
 * union of more than four operands has a chain of records, its operands in
 * order.  Lanes from n on are unused and never read. */
enum { WIDE = 4 };

typedef struct csg_wide {
    double box[2][3][WIDE]; /* box[0][k][i], box[1][k][i]: operand i's lo, hi on axis k */
    int32_t node[WIDE];     /* the operands' node indices */
    int32_t ref[WIDE];
    int32_t n;    /* operands in this record, 1 to WIDE */
    int32_t more; /* the union's next record, or -1 */
} csg_wide;

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
    csg_wide *wide; /* the unions' operand records (csg_fnode.wide) */
    int nwide;
    int32_t *roots; /* node index of each root, or -1 when empty */
    int nroots;
    int max_depth; /* deepest root, in nodes; sizes the trace's stack */
    int cull;      /* 1: test node bounds (0 only in tests, via csg_scene_set_cull) */
    int avx;       /* 1: csg_trace_first tests csg_wide boxes with AVX (the CPU has it) */
};

/* Testing hook: turn bounds culling off (0) or on (1) to check that culling
 * never changes a result.  Not thread-safe against concurrent traces. */
void csg_scene_set_cull(csg_scene *s, int on);

/* Testing hook: test csg_wide boxes with AVX (1, where the CPU has it) or
 * with scalar code (0), to check that the two agree bit for bit.  Returns
 * whether AVX is now used.  Not thread-safe against concurrent traces. */
int csg_scene_set_avx(csg_scene *s, int on);

/* Testing hook: csg_trace_first's box test of record w's operands (with
 * AVX or not, as csg_scene_set_avx chose) for the ray o + t·d over
 * [t0, t1]: bit i set when operand i's box is met, te[i] where the ray
 * enters it (defined for set bits).  The arena is only read. */
unsigned csg_scene_wide_entry(const csg_scene *s, int32_t w, const double o[3], const double d[3],
                              double t0, double t1, iv_arena *a, double te[WIDE]);

/* World bounds of the object box lo..hi under m: the AABB of the transformed
 * box, per axis t_i + Σ_j m_ij·[lo_j, hi_j] (Arvo 1990), which equals the
 * box of the 8 transformed corners; a zero coefficient contributes exactly
 * 0, so an infinite object extent only spreads to the world axes it maps
 * onto (scene.c). */
void csg_box_transform(const csg_affine m, const double lo[3], const double hi[3], double wlo[3],
                       double whi[3]);

/* Whether this CPU and OS run AVX code (csg_trace_first's box tests). */
int csg_cpu_has_avx(void);

#endif

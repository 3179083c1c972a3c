/*
 * bvh_split.h — the split both bounding hierarchies use (polyhedron
 * triangles here, union operands in src/csg): binned surface area
 * heuristic over boxes with their centres.
 */
#ifndef RAYSCAD_BVH_SPLIT_H
#define RAYSCAD_BVH_SPLIT_H

typedef struct iv_bvh_item {
    double lo[3], hi[3]; /* the element's box */
    double c[3];         /* its centre (any point of the box will do) */
    int id;              /* the caller's */
} iv_bvh_item;

/* Depth past which iv_bvh_split takes the median: every split then halves,
 * so a builder's recursion stays within IV_BVH_SAH_DEPTH + log2(m). */
enum { IV_BVH_SAH_DEPTH = 40 };

/* Split items[0..m) (m >= 2) in two, in place; returns the count l of the
 * left part, 0 < l < m.  Of the planes between 16 bins of the centres on
 * each axis, the one least in area(L)·|L| + area(R)·|R| — proportional to
 * the box tests a ray that meets the parent's box expects to make below
 * it; at `depth` >= IV_BVH_SAH_DEPTH, or when all centres coincide, the
 * median on the axis where the centres spread most. */
int iv_bvh_split(iv_bvh_item *items, int m, int depth);

#endif

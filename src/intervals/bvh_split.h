/*
 * bvh_split.h — the split both bounding hierarchies use (polyhedron
 * triangles here, union operands in src/csg): binned surface area
 * heuristic over boxes with their centres; and the clipping of long thin
 * triangles into several boxes before a mesh's hierarchy is built.
 */
#ifndef RAYSCAD_BVH_SPLIT_H
#define RAYSCAD_BVH_SPLIT_H

#include "intervals.h"

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

/* iv_bvh_split, and the boxes of the two parts (the union of their items'
 * boxes) into box[0] (left) and box[1] (right), each {lo, hi}, when box is
 * not NULL: the binning has them, and a builder need not pass over the
 * items again for them. */
int iv_bvh_split_boxes(iv_bvh_item *items, int m, int depth, double box[2][2][3]);

/* Early split clipping (Ernst and Greiner, "Early split clipping for
 * bounding volume hierarchies", 2007): items for the triangles tri[0..nt)
 * over the vertices v, one per triangle (its box, its centroid, id = its
 * index), and then up to `extra` more: while the budget lasts, the item
 * with the largest box among those whose box has over 8 times the area of
 * their part of the triangle is cut in two at the middle of its box's
 * longest side, each half boxing the triangle clipped to it.  The boxes of
 * one triangle's items cover the triangle (widened by 2^-40 of their
 * coordinates, as clipped vertices are rounded) and may overlap, so a ray
 * can meet a triangle through several of its items.  Returns a malloc'd
 * array of *nref items (the caller frees it); NULL when out of memory. */
iv_bvh_item *iv_bvh_clip_triangles(const double (*v)[3], const int (*tri)[3], int nt, long extra,
                                   long *nref);

/* iv_shape_mesh (intervals.h) with the budget of early split clipping
 * given: at most extra_per_triangle · (triangle count) references beyond
 * one per triangle; 0 builds the plain hierarchy.  *nref, when not NULL,
 * gets the number of references.  For tests that compare the two. */
int iv_shape_mesh_budget(iv_shape *s, const double (*verts)[3], int nverts, const int *faces,
                         const int *face_start, int nfaces, double extra_per_triangle, long *nref);

#endif

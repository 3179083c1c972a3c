/*
 * node.c — the mutable CSG tree that builders assemble before a commit.
 *
 * A node is a leaf (shape, world_from_object, material, copied at creation)
 * or an operation owning a growable array of children.  Ownership is strictly
 * a tree: every node has at most one owner, and an op node frees its
 * children.  Trees from OpenSCAD loops can be thousands of levels deep, so
 * freeing walks the tree through the `link` field instead of recursing.
 */
#include "csg_internal.h"

#include <stdlib.h>
#include <string.h>

csg_node *csg_node_shape(const iv_shape *s, const csg_affine world_from_object,
                         const csg_material *m)
{
    csg_node *n = calloc(1, sizeof *n);
    if (!n) return NULL;
    n->is_leaf = 1;
    n->shape = *s;
    iv_shape_retain(&n->shape); /* the node's own reference to shared data */
    memcpy(n->world_from_object, world_from_object, sizeof(csg_affine));
    n->material = *m;
    return n;
}

csg_node *csg_node_op(csg_op op)
{
    csg_node *n = calloc(1, sizeof *n);
    if (!n) return NULL;
    n->op = op;
    return n;
}

void csg_node_frame_whole(csg_node *n)
{
    if (n && !n->is_leaf) n->whole = 1;
}

int csg_node_add(csg_node *parent, csg_node *child)
{
    /* A NULL child is kept: it is an empty operand, which matters when it is
     * the first child of a difference. */
    if (!parent || parent->is_leaf) {
        csg_node_free(child);
        return -1;
    }
    if (parent->nkids == parent->cap) {
        int cap = parent->cap ? 2 * parent->cap : 4;
        csg_node **k = realloc(parent->kids, (size_t)cap * sizeof *k);
        if (!k) {
            csg_node_free(child);
            return -1;
        }
        parent->kids = k;
        parent->cap = cap;
    }
    parent->kids[parent->nkids++] = child;
    return 0;
}

int csg_node_child_count(const csg_node *n)
{
    return n && !n->is_leaf ? n->nkids : 0;
}

void csg_node_free(csg_node *n)
{
    /* A stack threaded through `link`: pop a node, push its children, free
     * it.  Constant extra memory whatever the depth. */
    csg_node *stack = n;
    if (n) n->link = NULL;
    while (stack) {
        csg_node *x = stack;
        stack = x->link;
        for (int i = 0; i < x->nkids; i++) {
            if (!x->kids[i]) continue;
            x->kids[i]->link = stack;
            stack = x->kids[i];
        }
        if (x->is_leaf) iv_shape_release(&x->shape);
        free(x->kids);
        free(x);
    }
}

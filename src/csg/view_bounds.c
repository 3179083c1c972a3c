/*
 * view_bounds.c — the box OpenSCAD frames.  OpenSCAD 2021.01 fits its view
 * (--viewall, --autocenter, the default view) to CSGProducts::getBoundingBox:
 * the union of the boxes of every leaf its normalised CSG products hold as a
 * positive term, however the intersections and differences above them trim
 * the solid (openscad_bounds says which those are).  To line our images up
 * with OpenSCAD's we frame the same box, computed on the flattened scene.
 *
 * Where that box is more than LOOSE times the size of what is drawn (the
 * scene's own bounds: intersections meet their operands' boxes), OpenSCAD
 * frames a speck or nothing at all — a model clipped by a 1e10 box is the
 * common case — and we frame what is drawn instead.  Across OpenSCAD's
 * regression corpus the ratio is at most 6.7 where its framing shows the
 * model.
 */
#include "csg_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define LOOSE 10.0

static double largest_side(const double lo[3], const double hi[3])
{
    double e = 0;
    for (int k = 0; k < 3; k++)
        if (hi[k] - lo[k] > e) e = hi[k] - lo[k];
    return e;
}

static int openscad_bounds(const csg_scene *s, int r, double lo[3], double hi[3]);

/* OpenSCAD frames a 2D object flat (its tessellated polygon at z = 0),
 * though its preview draws a slab: a prism leaf over that slab, z in
 * [-FLAT_SLAB, FLAT_SLAB] (src/scad's SCAD_SLAB), is boxed at z = 0. */
#define FLAT_SLAB 0.5

static void leaf_box(const csg_scene *s, const csg_fnode *f, double lo[3], double hi[3])
{
    const csg_prim *p = &s->prims[f->prim];
    const iv_shape *sh = &p->shape;
    double olo[3], ohi[3];
    csg_affine w;
    memcpy(lo, f->lo, 3 * sizeof *lo);
    memcpy(hi, f->hi, 3 * sizeof *hi);
    if (sh->kind != IV_SHAPE_PRISM || sh->u.prism.z0 != -FLAT_SLAB || sh->u.prism.z1 != FLAT_SLAB ||
        iv_shape_bounds(sh, olo, ohi) != 0 || csg_affine_invert(p->object_from_world, w) != 0)
        return;
    olo[2] = ohi[2] = 0;
    csg_box_transform(w, olo, ohi, lo, hi);
}

int csg_scene_view_bounds(const csg_scene *s, int r, double lo[3], double hi[3])
{
    double tlo[3], thi[3];
    if (openscad_bounds(s, r, lo, hi) != 0) return -1;
    if (csg_scene_bounds(s, r, tlo, thi) != 0) return 0;
    double drawn = largest_side(tlo, thi);
    if (drawn > 0 && largest_side(lo, hi) > LOOSE * drawn) {
        memcpy(lo, tlo, sizeof tlo);
        memcpy(hi, thi, sizeof thi);
    }
    return 0;
}

/* 1 when the boxes of nodes a and b meet. */
static int boxes_meet(const csg_scene *s, int a, int b)
{
    const csg_fnode *x = &s->nodes[a], *y = &s->nodes[b];
    for (int k = 0; k < 3; k++)
        if (x->lo[k] > y->hi[k] || y->lo[k] > x->hi[k]) return 0;
    return 1;
}

/* 1 when the boxes of every operand of intersection node i have a point in
 * common. */
static int operands_meet(const csg_scene *s, int i)
{
    const csg_fnode *f = &s->nodes[i];
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        lo[k] = -INFINITY;
        hi[k] = INFINITY;
    }
    for (int c = i + 1; c < f->next; c = s->nodes[c].next)
        for (int k = 0; k < 3; k++) {
            lo[k] = s->nodes[c].lo[k] > lo[k] ? s->nodes[c].lo[k] : lo[k];
            hi[k] = s->nodes[c].hi[k] < hi[k] ? s->nodes[c].hi[k] : hi[k];
        }
    for (int k = 0; k < 3; k++)
        if (lo[k] > hi[k]) return 0;
    return 1;
}

/* The union of the boxes of the leaves that OpenSCAD's normalised CSG
 * products hold as positive terms (CSGProducts::getBoundingBox).  The
 * normaliser rewrites x − (y − z) as (x − y) ∪ (x ∩ z), so a leaf is
 * positive when it lies in an even number of subtracted operands (the
 * second and later of a difference); and it prunes by boxes: a subtracted
 * operand whose box misses the first operand's goes, and so does an
 * intersection whose operands' boxes have no common point.  One forward
 * pass over the pre-order nodes: a parent precedes its children. */
static int openscad_bounds(const csg_scene *s, int r, double lo[3], double hi[3])
{
    if (r < 0 || r >= s->nroots || s->roots[r] < 0) return -1;
    int first = s->roots[r], end = s->nodes[first].next;
    /* per node: bit 0 subtracted an odd number of times, bit 1 pruned */
    unsigned char *st = calloc((size_t)(end - first), 1);
    if (!st) { /* fall back to the exact bounds, which lie inside */
        return csg_scene_bounds(s, r, lo, hi);
    }
    int found = 0;
    for (int i = first; i < end; i++) {
        const csg_fnode *f = &s->nodes[i];
        int si = st[i - first];
        if (f->op == FNODE_LEAF) {
            if (si) continue;
            double a[3], b[3];
            leaf_box(s, f, a, b);
            for (int k = 0; k < 3; k++) {
                lo[k] = found && lo[k] < a[k] ? lo[k] : a[k];
                hi[k] = found && hi[k] > b[k] ? hi[k] : b[k];
            }
            found = 1;
            continue;
        }
        if (f->whole && !si) {
            /* one piece of geometry in OpenSCAD's preview: its own box
             * (the node's, which meets an intersection's operands and is a
             * difference's first operand's), not its leaves' */
            for (int k = 0; k < 3; k++) {
                lo[k] = found && lo[k] < f->lo[k] ? lo[k] : f->lo[k];
                hi[k] = found && hi[k] > f->hi[k] ? hi[k] : f->hi[k];
            }
            found = 1;
            si = 2;
        }
        int pruned = (si & 2) || (f->op == CSG_OP_INTERSECTION && !operands_meet(s, i));
        for (int c = i + 1; c < f->next; c = s->nodes[c].next) {
            int sub = f->op == CSG_OP_DIFFERENCE && c != i + 1;
            int off = pruned || (sub && !boxes_meet(s, i + 1, c));
            st[c - first] = (unsigned char)(((si & 1) ^ sub) | (off ? 2 : 0));
        }
    }
    free(st);
    return found ? 0 : -1;
}

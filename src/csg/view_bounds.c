/*
 * view_bounds.c — the box OpenSCAD frames.  OpenSCAD 2021.01 fits its view
 * (--viewall, --autocenter, the default view) to CSGProduct::getBoundingBox:
 * the union of the boxes of every leaf that is not subtracted, however the
 * intersections and differences above them trim the solid.  To line our
 * images up with OpenSCAD's we frame the same box, computed on the flattened
 * scene: in pre-order a parent precedes its children, so one forward pass
 * marks each node subtracted or not (a difference's operands after the first
 * are subtracted, and so is everything below a subtracted node).
 *
 * Where that box is more than LOOSE times the size of what is drawn (the
 * scene's own bounds: intersections meet their operands' boxes), OpenSCAD
 * frames a speck or nothing at all — a model clipped by a 1e10 box is the
 * common case — and we frame what is drawn instead.  Across OpenSCAD's
 * regression corpus the ratio is at most 6.7 where its framing shows the
 * model.
 */
#include "csg_internal.h"

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

static int openscad_bounds(const csg_scene *s, int r, double lo[3], double hi[3])
{
    if (r < 0 || r >= s->nroots || s->roots[r] < 0) return -1;
    int first = s->roots[r], end = s->nodes[first].next;
    unsigned char *neg = calloc((size_t)(end - first), 1);
    if (!neg) { /* fall back to the exact bounds, which lie inside */
        return csg_scene_bounds(s, r, lo, hi);
    }
    int found = 0;
    for (int i = first; i < end; i++) {
        const csg_fnode *f = &s->nodes[i];
        int ni = neg[i - first];
        if (f->op == FNODE_LEAF) {
            if (ni) continue;
            double a[3], b[3];
            leaf_box(s, f, a, b);
            for (int k = 0; k < 3; k++) {
                lo[k] = found && lo[k] < a[k] ? lo[k] : a[k];
                hi[k] = found && hi[k] > b[k] ? hi[k] : b[k];
            }
            found = 1;
            continue;
        }
        for (int c = i + 1; c < f->next; c = s->nodes[c].next)
            neg[c - first] = (unsigned char)(ni || (f->op == CSG_OP_DIFFERENCE && c != i + 1));
    }
    free(neg);
    return found ? 0 : -1;
}

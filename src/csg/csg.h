/*
 * csg.h — the CSG tree: building it, finalising it into a read-only scene,
 * and tracing rays through it as interval lists.
 *
 * Build:   csg_node_shape / csg_node_op / csg_node_add make a tree; each leaf
 *          carries its full world_from_object transform and its material, so
 *          nothing multiplies matrices per ray.
 * Commit:  csg_scene_new takes the trees, computes bounds, inverse transforms
 *          and normal matrices, flattens them, and frees the nodes.
 * Query:   csg_trace, csg_trace_first, csg_scene_normal, csg_scene_material
 *          — read-only, so any number of threads may query one scene at once
 *          (each with its own iv_arena).
 */
#ifndef RAYSCAD_CSG_H
#define RAYSCAD_CSG_H

#include "../intervals/intervals.h"

typedef enum csg_op {
    CSG_OP_UNION,
    CSG_OP_INTERSECTION,
    CSG_OP_DIFFERENCE /* first child minus all the others */
} csg_op;

typedef struct csg_material {
    float rgba[4]; /* sRGB-encoded colour and alpha, each in [0, 1] */
    int has_color; /* 0: no color() applied; the renderer uses its scheme */
    int highlight; /* under a '#': the highlight colour wherever it is drawn, as
                      OpenSCAD's preview colours the flagged leaves in its main
                      pass too (its own colour unseen) */
    /* Optics for the renderer's opt-in light model (all 0: none, which is
     * OpenSCAD's look).  Set from $rs_ variables (src/scad/material.c). */
    float reflect;  /* mirror reflectivity in [0, 1] */
    float absorb;   /* Beer–Lambert coefficient per unit length, >= 0; 0: the
                       colour's alpha applies per surface instead */
    float ior;      /* index of refraction (> 1 refracts; 0: none) */
    float emit;     /* > 0: a light of this intensity (see light[]) */
    float light[4]; /* emitters: world centre x, y, z and radius */
} csg_material;

/* Affine transforms are 3×4 row-major: x' = m[0]x + m[1]y + m[2]z + m[3], … */
typedef double csg_affine[12];

extern const csg_affine csg_affine_identity;

typedef struct csg_node csg_node;

/* A leaf: shape s placed by world_from_object, with material m (both copied;
 * the node retains the shape's shared data, iv_shape_retain, and frees it).
 * Returns a node owned by the caller (csg_node_free, or hand it to a parent
 * or a scene), or NULL when out of memory. */
csg_node *csg_node_shape(const iv_shape *s, const csg_affine world_from_object,
                         const csg_material *m);
/* An operation with no children yet: an empty union, intersection or
 * difference is the empty set. */
csg_node *csg_node_op(csg_op op);
/* Mark op node n as one OpenSCAD's preview draws as a single piece of
 * geometry (render(), resize(), an extrusion: a CGAL leaf of its CSG
 * products), which its view framing boxes as a whole
 * (csg_scene_view_bounds) rather than by the leaves inside. */
void csg_node_frame_whole(csg_node *n);
/* Append child to parent (an op node); the parent owns it from now on, also
 * when this fails.  Returns 0, or -1 when out of memory. */
int csg_node_add(csg_node *parent, csg_node *child);
/* Number of children of an op node (0 for a leaf). */
int csg_node_child_count(const csg_node *n);
void csg_node_free(csg_node *n);

typedef struct csg_scene csg_scene;

/* Commit: takes ownership of the n root trees (each may be NULL = empty) and
 * frees them, whatever the outcome.  Leaves with a singular transform or an
 * empty shape are dropped (as OpenSCAD drops degenerate objects).
 * Returns the scene (free with csg_scene_free), or NULL with a message in
 * err (errlen bytes) when out of memory. */
csg_scene *csg_scene_new(csg_node **roots, int n, char *err, size_t errlen);
void csg_scene_free(csg_scene *s);

int csg_scene_root_count(const csg_scene *s);
/* Number of primitives (leaves); prim indices run 0 .. count-1. */
int csg_scene_prim_count(const csg_scene *s);

/* World-space bounds of root r.  Returns 0, or -1 when the root is empty
 * (then lo/hi are untouched).  Components may be infinite (halfspaces). */
int csg_scene_bounds(const csg_scene *s, int r, double lo[3], double hi[3]);

/* The box OpenSCAD 2021.01 frames for root r (--viewall, --autocenter, the
 * default view): the union of the world bounds of every leaf that is not
 * subtracted, however intersections and differences trim the solid.
 * Returns 0, or -1 when the root has no such leaf. */
int csg_scene_view_bounds(const csg_scene *s, int r, double lo[3], double hi[3]);

/* The interval list of root r along the world ray o + t·d, clipped to
 * [tmin, tmax].  Scratch and the result's storage come from arena a (the
 * result stays valid until the arena is reset).  Subtrees whose bounds the
 * ray misses are skipped, and so is every operand after the first of an
 * intersection or difference whose first operand is empty (Roth).  No list
 * made along the way (a leaf's, a merge's, the result) may hold more spans
 * than the arena's list limit, iv_arena_list_limit.
 * Returns 0, or -1 when the arena is out of memory or a list would pass
 * that limit; iv_arena_failure(a) then says which. */
int csg_trace(const csg_scene *s, int r, const double o[3], const double d[3], double tmin,
              double tmax, iv_arena *a, iv_list *out);

/* The first boundary of the list csg_trace returns for the same arguments —
 * the same t, prim, part and flip, bit for bit — into *hit, found without
 * the rest of the list: the operands of unions (and the subtrees of their
 * bounding hierarchy) are visited nearest box first and evaluated only up to
 * the nearest boundary found so far, so a ray through a wide union costs
 * about what its first hit costs.  For an opaque first surface, or a shadow
 * ray that any opaque surface stops, this is all a renderer needs.  Scratch
 * comes from arena a, and its lists obey the arena's list limit as
 * csg_trace's do.  Returns 1 with *hit set, 0 when the list is empty
 * (*hit untouched), or -1 as csg_trace fails (iv_arena_failure says why). */
int csg_trace_first(const csg_scene *s, int r, const double o[3], const double d[3], double tmin,
                    double tmax, iv_arena *a, iv_bound *hit);

/* The world-space unit normal at boundary b of a list traced along o + t·d:
 * the primitive's outward normal, negated when b->flip.  A boundary with
 * prim == IV_PRIM_NONE (a clip) gets -d normalised. */
void csg_scene_normal(const csg_scene *s, const iv_bound *b, const double o[3], const double d[3],
                      double n[3]);

/* The world-space surface through boundary b of a list traced along
 * o + t·d, as a quadric whose gradient at the boundary points along
 * csg_scene_normal's normal (a plane: A = 0, b that normal): where the
 * boundary goes as the ray moves, while it stays on that part.  0, or -1
 * for a clip or an infinite t. */
int csg_scene_quadric(const csg_scene *s, const iv_bound *b, const double o[3], const double d[3],
                      iv_quadric *q);

/* The material of primitive prim (borrowed from the scene). */
const csg_material *csg_scene_material(const csg_scene *s, int32_t prim);

/* ---- small affine helpers, shared by the builders ------------------------ */

/* out = a ∘ b (apply b first).  out may alias a or b. */
void csg_affine_mul(const csg_affine a, const csg_affine b, csg_affine out);
/* Inverse of m into out; returns 0, or -1 when m is singular (|det| tiny
 * relative to the scale of m) or not finite. */
int csg_affine_invert(const csg_affine m, csg_affine out);
void csg_affine_point(const csg_affine m, const double p[3], double out[3]);
void csg_affine_vector(const csg_affine m, const double v[3], double out[3]);
/* The determinant of m's linear part (< 0: m mirrors). */
double csg_affine_det(const csg_affine m);

/* ---- reading a committed scene (src/csg/inspect.c) -----------------------
 * For exporters: the flattened, simplified tree as the tracer sees it.  Node
 * indices run 0 .. csg_scene_node_count-1 in pre-order; the children of an
 * op node i are i + 1 and then, while below info.end, each child's end. */

typedef struct csg_scene_node_info {
    int is_leaf;
    csg_op op;           /* op nodes */
    int32_t prim;        /* leaves: the primitive index */
    int32_t end;         /* index just past this node's subtree */
    double lo[3], hi[3]; /* world bounds, padded; may be infinite */
} csg_scene_node_info;

int csg_scene_node_count(const csg_scene *s);
/* The node index of root r, or -1 when that root is empty or out of range. */
int32_t csg_scene_root_node(const csg_scene *s, int r);
/* Fill *out for node i (0 <= i < csg_scene_node_count). */
void csg_scene_node_get(const csg_scene *s, int32_t i, csg_scene_node_info *out);
/* The shape of primitive prim (borrowed from the scene). */
const iv_shape *csg_scene_prim_shape(const csg_scene *s, int32_t prim);
/* The world_from_object transform of primitive prim into out (the inverse
 * of the one the tracer keeps, so equal to the built one up to rounding). */
void csg_scene_prim_transform(const csg_scene *s, int32_t prim, csg_affine out);

#endif

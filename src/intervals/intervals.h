/*
 * intervals.h — interval lists along a ray, their boolean merges, and the
 * ray–primitive intersections that produce them.
 *
 * A ray is o + t·d.  An interval list is a sorted sequence of disjoint spans
 * [enter.t, exit.t] with enter.t < exit.t and span[i].exit.t < span[i+1].enter.t
 * (touching spans are merged).  Ends may be ±INFINITY (halfspaces).  Every
 * boundary remembers the primitive that made it (an index chosen by the caller),
 * the part of that primitive (a box face, a cylinder cap…) and whether its
 * normal is flipped (it came from a subtracted solid).
 *
 * Nothing here allocates per ray except through an iv_arena, which is reset,
 * not freed, between rays: after warm-up the steady state makes no malloc.
 */
#ifndef RAYSCAD_INTERVALS_H
#define RAYSCAD_INTERVALS_H

#include <stddef.h>
#include <stdint.h>

#include "angles.h"

/* ---- arena -------------------------------------------------------------- */

/* A bump allocator made of chunks.  Memory handed out stays valid until
 * iv_arena_reset or iv_arena_free.  One arena per thread. */
typedef struct iv_arena iv_arena;

/* Returns a new arena (owned by the caller, free with iv_arena_free), or NULL
 * when out of memory.  first_chunk is a size hint in bytes (0: a default). */
iv_arena *iv_arena_new(size_t first_chunk);
void iv_arena_free(iv_arena *a);
/* Returns 16-byte aligned memory for `bytes`, or NULL when out of memory or
 * when the arena's limit (iv_arena_set_limit) would be passed (recorded as
 * IV_ARENA_OUT_OF_MEMORY, see iv_arena_failure). */
void *iv_arena_alloc(iv_arena *a, size_t bytes);
/* Forget every allocation; keeps the chunks for reuse.  The recorded
 * failure (iv_arena_failure) stays. */
void iv_arena_reset(iv_arena *a);
/* Cap on the total bytes the arena may hold (0 = no cap). */
void iv_arena_set_limit(iv_arena *a, size_t bytes);

/* The arena is also where a thread's per-ray work keeps its limit and its
 * first failure, since every query of that work takes the arena: a worker
 * that sees a query fail asks the arena why, after the fact, without every
 * caller in between passing a reason along.
 *
 * IV_LIST_LIMIT_DEFAULT: the spans one interval list may hold while a ray
 * is evaluated (csg_trace).  2^20 spans are 32 MiB; a ray would have to
 * cross a million separate pieces of solid to need them, so a list that
 * long comes from a runaway model (a loop unioning thin slabs along one
 * line), and the limit stops it before the per-thread scratch grows by
 * gigabytes. */
enum { IV_LIST_LIMIT_DEFAULT = 1 << 20 };

/* Set the spans one list may hold (n >= 1; n <= 0 restores the default);
 * iv_arena_list_limit reads it back. */
void iv_arena_set_list_limit(iv_arena *a, int n);
int iv_arena_list_limit(const iv_arena *a);

typedef enum iv_arena_failure_kind {
    IV_ARENA_OK = 0,
    IV_ARENA_OUT_OF_MEMORY, /* malloc refused, or the byte cap was reached */
    IV_ARENA_LIST_TOO_LONG  /* a list would pass iv_arena_list_limit */
} iv_arena_failure_kind;

/* The first failure since the arena was made: iv_arena_alloc records
 * OUT_OF_MEMORY when it returns NULL, and users of the arena record what
 * they detect (csg_trace: LIST_TOO_LONG).  Later failures do not overwrite
 * the first one; iv_arena_clear_failure forgets it. */
iv_arena_failure_kind iv_arena_failure(const iv_arena *a);
void iv_arena_record_failure(iv_arena *a, iv_arena_failure_kind why);
void iv_arena_clear_failure(iv_arena *a);

/* ---- interval lists ----------------------------------------------------- */

enum {
    IV_PRIM_NONE = -1 /* a boundary made by clipping, not by a surface */
};

typedef struct iv_bound {
    double t;
    int32_t prim;  /* caller's primitive index, or IV_PRIM_NONE */
    uint16_t part; /* which face/part of the primitive (shape-specific) */
    uint16_t flip; /* 1: the outward normal of the result is minus the
                      primitive's outward normal (subtracted surface) */
} iv_bound;

typedef struct iv_span {
    iv_bound enter, exit;
} iv_span;

/* A list borrows its storage: `v` holds `cap` spans, `n` are in use. */
typedef struct iv_list {
    iv_span *v;
    int n;
    int cap;
} iv_list;

/* Give `l` room for `cap` spans from the arena; n = 0.  Returns 0, or -1
 * when the arena is out of memory. */
int iv_list_init(iv_list *l, int cap, iv_arena *a);

/* The boolean merges.  Each is one linear pass over both inputs (Roth 1982,
 * classify and combine).  `out` must not alias an input and must have
 * cap >= a->n + b->n (an upper bound for every operation).  Results obey the
 * list invariant: touching spans merge, empty spans vanish.
 * Difference flips the boundaries that come from b. */
void iv_list_union(const iv_list *a, const iv_list *b, iv_list *out);
void iv_list_intersection(const iv_list *a, const iv_list *b, iv_list *out);
void iv_list_difference(const iv_list *a, const iv_list *b, iv_list *out);

/* Keep only the part of `l` inside [tmin, tmax], in place.  A span cut by the
 * clip gets a boundary with prim = IV_PRIM_NONE at the cut. */
void iv_list_clip(iv_list *l, double tmin, double tmax);

/* 1 when t lies inside some span of l (closed ends), else 0. */
int iv_list_contains(const iv_list *l, double t);

/* ---- primitives ----------------------------------------------------------- */

typedef enum iv_shape_kind {
    IV_SHAPE_HALFSPACE, /* n·x <= d */
    IV_SHAPE_SPHERE,    /* |x| <= r, centred on the origin */
    IV_SHAPE_BOX,       /* lo <= x <= hi */
    IV_SHAPE_CONE,      /* 0 <= z <= h, x²+y² <= r(z)², r(z) = r1 + (r2-r1)·z/h */
    IV_SHAPE_POLYTOPE,  /* convex: n·x <= d for every plane of an iv_polytope */
    IV_SHAPE_MESH,      /* inside a closed triangle mesh (iv_mesh), nonzero rule; or
                           an open one's faces as thin spans (iv_shape_polyhedron) */
    IV_SHAPE_PRISM,     /* z0 <= z <= z1 and (x, y) in a 2D region (or a disc) */
    IV_SHAPE_REVOLVE    /* (sqrt(x²+y²), z) in a 2D region, azimuth in [0, angle] */
} iv_shape_kind;

/* Parts, for iv_bound.part. */
enum {
    IV_PART_SURFACE = 0, /* the only part of a halfspace or sphere */
    /* box faces: -x, +x, -y, +y, -z, +z */
    IV_PART_BOX_XMIN = 0,
    IV_PART_BOX_XMAX,
    IV_PART_BOX_YMIN,
    IV_PART_BOX_YMAX,
    IV_PART_BOX_ZMIN,
    IV_PART_BOX_ZMAX,
    /* cone: the curved side and the two caps */
    IV_PART_CONE_SIDE = 0,
    IV_PART_CONE_BOTTOM, /* z = 0 */
    IV_PART_CONE_TOP,    /* z = h */
    /* polytope: the plane index; mesh: the triangle index modulo 65536 (the
     * normal picks the candidate whose plane passes nearest the point) */
    /* prism: the two caps, then edge e of the region as IV_PART_PRISM_EDGE + e
     * (modulo 65536, resolved like a mesh's) */
    IV_PART_PRISM_BOTTOM = 0, /* z = z0 */
    IV_PART_PRISM_TOP,        /* z = z1 */
    IV_PART_PRISM_EDGE,
    /* revolve: edge e of the profile, then the two end half-planes */
    IV_PART_REVOLVE_START = 0xfffe, /* azimuth 0 */
    IV_PART_REVOLVE_END = 0xffff    /* azimuth = angle */
};

/* Immutable, reference-counted data behind the shapes that need more than a
 * few numbers.  Each is built once (single-threaded) and then only read, by
 * any number of threads.  See iv_shape_retain. */
typedef struct iv_polytope iv_polytope;
typedef struct iv_mesh iv_mesh;
typedef struct iv_region iv_region;

typedef struct iv_shape {
    iv_shape_kind kind;
    union {
        struct {
            double n[3], d;
        } halfspace;
        struct {
            double r;
        } sphere;
        struct {
            double lo[3], hi[3];
        } box;
        struct {
            double r1, r2, h;
        } cone;
        struct {
            iv_polytope *p;
        } polytope;
        struct {
            iv_mesh *m;
        } mesh;
        struct {
            iv_region *g;
            double r, z0, z1;
        } prism; /* g NULL: the disc |xy| <= r */
        struct {
            iv_region *g;
            double angle;
            int fragments; /* OpenSCAD's steps over angle; 0 unknown (rays ignore it) */
        } revolve;         /* angle in degrees, (0, 360] */
    } u;
} iv_shape;

/* ---- shape data and ownership --------------------------------------------
 * A shape of kind POLYTOPE, MESH, PRISM (with a region) or REVOLVE holds one
 * reference to its data.  iv_shape is copied by value, so whoever copies one
 * and keeps both copies calls iv_shape_retain on the copy; whoever drops a
 * copy calls iv_shape_release.  csg_node_shape retains its copy,
 * csg_node_free and csg_scene_free release theirs.  Both are no-ops for the
 * other kinds, so callers need not look at the kind.  The counts are atomic,
 * but a scene is built before it is shared, so only builders touch them. */
void iv_shape_retain(const iv_shape *s);
void iv_shape_release(iv_shape *s);

/* A convex polytope: the planes n·x <= d (planes[i] = {nx, ny, nz, d}, n need
 * not be unit; it is normalised) and, for bounds and hulls, the vertices.
 * Returns a shape holding the only reference, 0; or -1 when out of memory,
 * n is 0 or more than 65536 planes, or a value is not finite. */
int iv_shape_polytope(iv_shape *s, const double (*planes)[4], int nplanes, const double (*verts)[3],
                      int nverts);
/* Tell polytope s which faces border which: tri[i] is the triangle of the
 * hull that plane i is the plane of, as indices into its vertices (in
 * order, counter-clockwise from outside).  Lines then walk from face to
 * face instead of clipping against every plane (polytope.c), and the
 * triangles are kept (iv_polytope_triangles).  0; or -1 when the
 * triangles do not close up (every edge once each way) or out of memory. */
int iv_polytope_set_faces(iv_shape *s, const int (*tri)[3]);
/* The triangles iv_polytope_set_faces kept, one per plane (*n of them), or
 * NULL (other kinds, or none given).  For meshes written as the polytope's
 * own faces. */
const int32_t (*iv_polytope_triangles(const iv_shape *s, int *n))[3];
/* The vertices of a polytope (borrowed), or NULL for other kinds. */
const double (*iv_polytope_vertices(const iv_shape *s, int *n))[3];
/* The planes of a polytope (borrowed): {nx, ny, nz, d} with unit n, inside
 * where n·x <= d; or NULL for other kinds.  For exporters. */
const double (*iv_polytope_planes(const iv_shape *s, int *n))[4];

/* A mesh from polygonal faces given as vertex indices (OpenSCAD's winding:
 * clockwise seen from outside).  Each face is fan-triangulated; the hit
 * counting is by signed crossings, so a fan is exact for any simple planar
 * face, convex or not.  faces[face_start[i] .. face_start[i+1]) index verts.
 * Returns 0, 1 when the mesh is not closed (every edge used once each way) —
 * the shape is still made, best effort — or -1 on a bad index, no faces,
 * non-finite values or out of memory (then s is untouched). */
int iv_shape_mesh(iv_shape *s, const double (*verts)[3], int nverts, const int *faces,
                  const int *face_start, int nfaces);
/* A mesh from faces as a user wrote them (polyhedron(), an imported file),
 * read as OpenSCAD reads them: a closed surface is a solid whatever its
 * faces' winding (they are turned as needed, a cavity kept a cavity); one
 * cracked only at T-junctions is a solid all the same; one with holes, or
 * one-sided, is a sheet with no inside — each face drawn, as OpenSCAD's
 * preview draws it — whose crossings are spans a billionth of its size
 * thick.  Returns 0 (closed as wound), 1 (faces turned), 2 (cracked),
 * 3 (a sheet), or -1 as iv_shape_mesh. */
int iv_shape_polyhedron(iv_shape *s, const double (*verts)[3], int nverts, const int *faces,
                        const int *face_start, int nfaces);
/* As iv_shape_polyhedron, but a surface with holes is read best effort as
 * a solid (the signed crossings) rather than as a sheet: for a mesh, which
 * needs an inside (openscad's render of an open polyhedron exports its
 * faces as given, which no mesh of ours can be).  Same returns. */
int iv_shape_polyhedron_solid(iv_shape *s, const double (*verts)[3], int nverts, const int *faces,
                              const int *face_start, int nfaces);
/* Vertices of a mesh (borrowed) or NULL. */
const double (*iv_mesh_vertices(const iv_shape *s, int *n))[3];
/* Triangles of a mesh as vertex index triples (borrowed; wound as the input
 * faces, in no particular order), or NULL for other kinds.  For exporters. */
const int (*iv_mesh_triangles(const iv_shape *s, int *n))[3];
/* Signed volume of a mesh (positive when its faces wind as OpenSCAD's). */
double iv_mesh_volume(const iv_shape *s);

/* A 2D region: closed paths under the even-odd rule; paths[path_start[i] ..
 * path_start[i+1]) are the points of path i.  Returns the region holding one
 * reference (owned by the caller: iv_region_release), or NULL when out of
 * memory or no path has 3 points. */
iv_region *iv_region_new(const double (*pts)[2], const int *path_start, int npaths);
void iv_region_retain(iv_region *g);
void iv_region_release(iv_region *g);
/* Points of a region in path order (borrowed). */
const double (*iv_region_points(const iv_region *g, int *n))[2];
/* Path boundaries: path i is points [start[i], start[i+1]); *npaths set. */
const int *iv_region_paths(const iv_region *g, int *npaths);
/* 1 when (x, y) is inside under the even-odd rule. */
int iv_region_contains(const iv_region *g, double x, double y);

/* A prism over region g (retained by the shape) between z0 < z1. */
void iv_shape_prism(iv_shape *s, iv_region *g, double z0, double z1);
/* The solid swept by region g (x >= 0) about the z axis from azimuth 0 to
 * angle degrees, counter-clockwise.  g is retained. */
void iv_shape_revolve(iv_shape *s, iv_region *g, double angle);

/* An upper bound on the spans iv_shape_intersect may append for s (1 for the
 * convex kinds); the caller's list needs that much room. */
int iv_shape_max_spans(const iv_shape *s);

/* Intersect the whole object-space line o + t·d, t in (-inf, inf), with shape
 * s (d need not be unit length; t is the caller's parameter, so it is the same
 * in world space when o and d are mapped by the same affine transform).
 * Appends at most iv_shape_max_spans(s) spans to `out` (one for the convex
 * kinds; a mesh, prism or revolve may use its spare room as scratch) whose
 * boundaries carry `prim` and their part.  Tangent and grazing rays and
 * zero-length hits give no span; a line inside a halfspace or parallel to and
 * inside a slab gives infinite ends; the result is never NaN.  The caller
 * clips to its [tmin, tmax].
 * Returns the number of spans appended, or -1 when out->cap is
 * exceeded. */
int iv_shape_intersect(const iv_shape *s, const double o[3], const double d[3], int32_t prim,
                       iv_list *out);

/* The outward unit normal of s at object-space point p on the given part. */
void iv_shape_normal(const iv_shape *s, const double p[3], int part, double n[3]);

/* An implicit quadric surface xᵀAx + b·x + c = 0 (A symmetric). */
typedef struct iv_quadric {
    double A[3][3], b[3], c;
} iv_quadric;

/* The surface that part of s through object-space point p lies on, when it
 * is curved: 1 with *q set (its sign unchosen: the caller orients it by the
 * normal); 0 when that part is flat (its plane: the normal through p). */
int iv_shape_quadric(const iv_shape *s, const double p[3], int part, iv_quadric *q);

/* Object-space bounds; infinite components are ±INFINITY.  Returns 0, or -1
 * when the shape is empty (e.g. r <= 0). */
int iv_shape_bounds(const iv_shape *s, double lo[3], double hi[3]);

/* ---- bounding hierarchies ---------------------------------------------------
 * The split both bounding hierarchies use (polyhedron triangles here, union
 * operands in src/csg, bvh_split.c): binned surface area heuristic over
 * boxes with their centres; and the clipping of long thin triangles into
 * several boxes before a mesh's hierarchy is built. */

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

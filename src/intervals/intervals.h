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

/* ---- arena -------------------------------------------------------------- */

/* A bump allocator made of chunks.  Memory handed out stays valid until
 * iv_arena_reset or iv_arena_free.  One arena per thread. */
typedef struct iv_arena iv_arena;

/* Returns a new arena (owned by the caller, free with iv_arena_free), or NULL
 * when out of memory.  first_chunk is a size hint in bytes (0: a default). */
iv_arena *iv_arena_new(size_t first_chunk);
void iv_arena_free(iv_arena *a);
/* Returns 16-byte aligned memory for `bytes`, or NULL when out of memory or
 * when the arena's limit (iv_arena_set_limit) would be passed. */
void *iv_arena_alloc(iv_arena *a, size_t bytes);
/* Forget every allocation; keeps the chunks for reuse. */
void iv_arena_reset(iv_arena *a);
/* Cap on the total bytes the arena may hold (0 = no cap). */
void iv_arena_set_limit(iv_arena *a, size_t bytes);

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
    IV_SHAPE_CONE       /* 0 <= z <= h, x²+y² <= r(z)², r(z) = r1 + (r2-r1)·z/h */
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
    IV_PART_CONE_TOP     /* z = h */
};

typedef struct iv_shape {
    iv_shape_kind kind;
    union {
        struct { double n[3], d; } halfspace;
        struct { double r; } sphere;
        struct { double lo[3], hi[3]; } box;
        struct { double r1, r2, h; } cone;
    } u;
} iv_shape;

/* Intersect the whole object-space line o + t·d, t in (-inf, inf), with shape
 * s (d need not be unit length; t is the caller's parameter, so it is the same
 * in world space when o and d are mapped by the same affine transform).
 * Appends at most one span to `out` (all current shapes are convex) whose
 * boundaries carry `prim` and their part.  Tangent and grazing rays and
 * zero-length hits give no span; a line inside a halfspace or parallel to and
 * inside a slab gives infinite ends; the result is never NaN.  The caller
 * clips to its [tmin, tmax].
 * Returns the number of spans appended (0 or 1), or -1 when out->cap is
 * exceeded. */
int iv_shape_intersect(const iv_shape *s, const double o[3], const double d[3],
                       int32_t prim, iv_list *out);

/* The outward unit normal of s at object-space point p on the given part. */
void iv_shape_normal(const iv_shape *s, const double p[3], int part, double n[3]);

/* Object-space bounds; infinite components are ±INFINITY.  Returns 0, or -1
 * when the shape is empty (e.g. r <= 0). */
int iv_shape_bounds(const iv_shape *s, double lo[3], double hi[3]);

#endif

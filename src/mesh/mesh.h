/*
 * mesh.h — triangle meshes and measurements from the same ray queries the
 * renderer makes.
 *
 * A model is sampled by three families of axis-aligned rays (tri-dexels): one
 * ray along x through every (y, z) node of a regular grid of spacing h, one
 * along y through every (x, z) node, one along z through every (x, y) node.
 * Every grid edge lies on one of those rays, so where the surface crosses an
 * edge is known exactly, with the exact normal there (Hermite data).
 *
 *   mesh_dexels_new      cast the rays once (the expensive step);
 *   mesh_dexels_measure  volume, area, bounds, centre of mass from them;
 *   mesh_dexels_contour  a closed, 2-manifold, outward-oriented triangle mesh.
 *
 * mesh_from_scene and mesh_measure_scene do both steps in one call.  Nothing
 * here prints; fallible calls return 0 or -1 with a message in err.
 */
#ifndef RAYSCAD_MESH_H
#define RAYSCAD_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "../../include/rayscad.h"
#include "../csg/csg.h"

/* Options, measurements and thin features are the public plain-data types
 * of rayscad.h (rayscad_mesh_options: grid spacing h or cells_per_side,
 * threads, root, feature angle, max_cells, max_intervals). */
typedef rayscad_mesh_options mesh_options;
typedef rayscad_measurement mesh_measure;
typedef rayscad_thin mesh_thin;

/* 2^32 cells: a cube of about 1625 cells a side, 12.7 times finer than the
 * default 128 — minutes of contouring and a mesh of gigabytes, so a grid
 * past it is taken for a mistake (a --mesh-size in the wrong unit) and
 * refused before anything is allocated for it. */
#define MESH_MAX_CELLS_DEFAULT (1LL << 32)

/* Fill o with the defaults (h derived from the model, all CPUs, root 0). */
void mesh_options_default(mesh_options *o);

/* The fallible calls below return 0, RAYSCAD_ERROR, or (so that a caller
 * can name the limit that was hit; the message says it in words)
 * RAYSCAD_ERROR_INTERVALS (a ray's interval list passed o->max_intervals)
 * or RAYSCAD_ERROR_CELLS (the grid has more than o->max_cells cells). */

/* ---- sampling ----------------------------------------------------------- */

/* The crossings of the three ray families with one root of a scene: O(surface)
 * memory (a few dozen bytes per crossing plus one offset per ray). */
typedef struct mesh_dexels mesh_dexels;

/* Cast the rays through root o->root of s (o may be NULL: defaults), on one
 * grid for each far-apart part of the model, of spacing o->h or chosen as
 * grids.c says (refined for thin parts when o->resolve_thin).  The
 * scene is borrowed until the sampling is freed: contouring casts rays of
 * its own into it (snap.c, refine.c).  An empty root, or a
 * root index out of range, gives an empty sampling (volume 0, empty mesh).
 * The result does not depend on the number of threads.  Returns 0 and the sampling in
 * *out (owned by the caller, free with mesh_dexels_free), or with a message
 * in err (errlen bytes) RAYSCAD_ERROR_CELLS (each grid checked before it is
 * cast; a refinement that would pass the limit is not made), RAYSCAD_ERROR_INTERVALS, or -1:
 * unbounded root (a halfspace left unintersected), a grid larger than 65536 cells per side or 2^31
 * rays per family, out of memory. */
int mesh_dexels_new(const csg_scene *s, const mesh_options *o, mesh_dexels **out, char *err,
                    size_t errlen);
void mesh_dexels_free(mesh_dexels *d);

/* The grid actually used: spacing h, the world position of node (0,0,0) and
 * the number of cells per axis (nodes = cells + 1).  An empty sampling
 * reports n = {0,0,0}. */
void mesh_dexels_grid(const mesh_dexels *d, double *h, double origin[3], int n[3]);

/* ---- measurement -------------------------------------------------------- */

/* Measure a sampling.  Never fails. */
void mesh_dexels_measure(const mesh_dexels *d, mesh_measure *out);

/* ---- thin features ------------------------------------------------------ */

/* Walls (of solid) and gaps (of empty space between two surfaces) thinner
 * than a given thickness, found along the rays.  A chord between two
 * consecutive crossings of a ray counts when the surfaces at its ends face
 * away from each other, nearly parallel (outward normals n0, n1 with
 * n0·n1 < MESH_THIN_COS, i.e. within about 26° of opposite), and its
 * thickness across them, chord length × (|n0·axis| + |n1·axis|) / 2, is
 * below the limit.  The normal test leaves out the short chords every ray
 * cuts where it grazes a curved surface (their two normals nearly agree)
 * and the tips of ordinary edges and cones; it keeps parallel faces closer
 * than the limit, which a grid of that spacing can miss entirely (both
 * faces between two nodes) or show with holes. */
#define MESH_THIN_COS (-0.9)

/* Refining the default grid (rayscad_mesh_options.resolve_thin): walls and
 * gaps thinner than MESH_REFINE_CELLS cells count when they hold more than
 * MESH_REFINE_SHARE of the volume; the grid may become up to
 * MESH_REFINE_MAX times finer, in up to MESH_REFINE_ROUNDS resamplings,
 * while the crossings stay within about MESH_REFINE_CROSSINGS (the
 * contour's output grows with them: about 2 triangles each). */
#define MESH_REFINE_CELLS 4.0
#define MESH_REFINE_SHARE 1e-3
#define MESH_REFINE_MAX 16.0
#define MESH_REFINE_ROUNDS 3
#define MESH_REFINE_CROSSINGS (1 << 20)

/* Find walls and gaps thinner than `thickness` (model units; the grid
 * spacing is the limit a contour can resolve).  Never fails. */
void mesh_dexels_thin(const mesh_dexels *d, double thickness, mesh_thin *out);

/* ---- meshes ------------------------------------------------------------- */

/* An indexed triangle mesh: vertices as 3 floats (x, y, z in model units),
 * triangles as 3 vertex indices, counter-clockwise seen from outside (the
 * right-hand normal points out of the solid).  Vertices are computed in
 * double and stored as float (as STL stores them): a model smaller than
 * about 1e-4 of its distance from the origin has h/256 below a float ulp
 * there, and its nearly coincident vertices may round together. */
typedef struct mesh mesh;

/* Contour a sampling (o may be NULL: defaults; only feature_angle_deg is
 * read).  The result is closed and 2-manifold (every edge in exactly two
 * triangles, with opposite directions; every vertex's triangles form one
 * fan), oriented outward, without zero-area triangles, and every vertex lies
 * within its grid cell (so within about h·√3 of the surface).  Features
 * thinner than about h may be lost or merged.  Returns 0 and the mesh in
 * *out (owned by the caller, free with mesh_free), or -1 with a message
 * (out of memory, more than 2^31 vertices). */
int mesh_dexels_contour(const mesh_dexels *d, const mesh_options *o, mesh **out, char *err,
                        size_t errlen);

/* The contour m of d simplified to within about tol of the exact surface
 * (balance.c): mesh_simplify, the smooth parts' sag then split between
 * both sides of the surface by moving their vertices out, and their
 * triangles still farther than tol split (tighten.c).  d's scene must
 * still be there.  0, or -1 with a message. */
int mesh_dexels_simplify(const mesh_dexels *d, mesh *m, double tol, const mesh_options *o,
                         char *err, size_t errlen);

/* The threads o asks for (o may be NULL; 0: one per CPU), at most 256. */
int mesh_thread_count(const mesh_options *o);

/* mesh_dexels_new + mesh_dexels_contour (+ mesh_dexels_simplify when
 * o->tolerance > 0) (+ measure when m is not NULL);
 * either's failure code. */
int mesh_from_scene(const csg_scene *s, const mesh_options *o, mesh **out, mesh_measure *m,
                    char *err, size_t errlen);
/* mesh_dexels_new + mesh_dexels_measure; mesh_dexels_new's failure code. */
int mesh_measure_scene(const csg_scene *s, const mesh_options *o, mesh_measure *out, char *err,
                       size_t errlen);

/* How far mesh_measure_exact may go: at most max_rays rays (<= 0: no
 * limit) whose lists hold at most max_intervals (0: the default), and it
 * stops where cancelled (NULL: never; asked from its threads every few
 * thousand rays) returns nonzero. */
typedef struct mesh_exact_limits {
    long long max_rays;
    int max_intervals;
    int (*cancelled)(void *cancel_ud);
    void *cancel_ud;
} mesh_exact_limits;

/* Volume, surface area, centre of mass and bounds of root `root` of s
 * integrated from rays to a relative tolerance tol (exact.c) within
 * limits; out->crossings is the number of rays cast.  0,
 * RAYSCAD_ERROR_RAYS, RAYSCAD_ERROR_INTERVALS, RAYSCAD_CANCELLED or -1,
 * with a message. */
int mesh_measure_exact(const csg_scene *s, int root, double tol, const mesh_exact_limits *limits,
                       mesh_measure *out, char *err, size_t errlen);

void mesh_free(mesh *m);
int mesh_vertex_count(const mesh *m);
int mesh_triangle_count(const mesh *m);
/* 3 × mesh_vertex_count floats, borrowed from m (valid until mesh_free). */
const float *mesh_vertices(const mesh *m);
/* 3 × mesh_triangle_count indices, borrowed from m. */
const int32_t *mesh_triangles(const mesh *m);

/* The colours of the model's color() calls the surface shows (0: none):
 * mesh_colors holds 4 floats each (sRGB and alpha in [0, 1]), and
 * mesh_triangle_colors a number per triangle, k for colour k - 1 or 0 for
 * a surface of no color(); both NULL without colours.  Each triangle takes
 * the colour of the primitive whose surface it is drawn from (a subtracted
 * one's on the faces it cuts), so colours meet along sharp edges. */
int mesh_color_count(const mesh *m);
const float *mesh_colors(const mesh *m);
const uint16_t *mesh_triangle_colors(const mesh *m);

/* Build a mesh from copies of caller arrays (e.g. one read back from a
 * file).  Indices are checked to lie in [0, nv).  Returns NULL when out of
 * memory or an index is out of range. */
mesh *mesh_new_from_arrays(const float *v, int nv, const int32_t *t, int nt);

/* Signed volume enclosed (positive for an outward-oriented closed mesh) and
 * total area, summed in double precision. */
double mesh_signed_volume(const mesh *m);
double mesh_area(const mesh *m);

/* The share of m's vertices where three sharp edges or more meet (edges
 * whose triangles' normals are more than 20° apart, or open ones): one in
 * a few on a surface of facets finer than the grid (a heightmap), a box's
 * eight on a plane-faced part; -1 when out of memory. */
double mesh_corner_share(const mesh *m);

#endif

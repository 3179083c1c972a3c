/*
 * dexels.h — private to src/mesh: the layout of a tri-dexel sampling and of
 * a mesh under construction, shared by dexels.c, contour.c and mesh.c.
 */
#ifndef RAYSCAD_MESH_DEXELS_H
#define RAYSCAD_MESH_DEXELS_H

#include "mesh.h"

/* One crossing of a ray with the surface.  t is measured from the grid
 * origin along the ray's axis (world coordinate = origin[axis] + t). */
typedef struct mesh_hit {
    double t;
    float n[3];     /* outward unit normal at the crossing */
    uint32_t patch; /* the face of the primitive it lies on (mesh_patch_of) */
    int16_t enter;  /* 1: the ray (going +axis) enters the solid here */
    uint16_t color; /* the surface's colour in the grid's palette; 0: none */
} mesh_hit;

/* The distinct color() values of a root's leaves (palette.c): colour k (1
 * .. n) is rgba[k - 1], sRGB and alpha in [0, 1]; of_prim[prim] is the
 * colour of primitive prim, 0 when none was given (or past
 * MESH_PALETTE_MAX colours). */
#define MESH_PALETTE_MAX 65535
typedef struct mesh_palette {
    float (*rgba)[4];
    int n;
    uint16_t *of_prim;
    int32_t nprim;
} mesh_palette;

/* 0, or -1 when out of memory (*p then empty). */
int mesh_palette_build(const csg_scene *s, int root, mesh_palette *p);
uint16_t mesh_palette_of(const mesh_palette *p, int32_t prim);
void mesh_palette_free(mesh_palette *p);

/* A closed triangle mesh, counter-clockwise from outside, triangle i of
 * colour color[i] (in the grid's palette). */
typedef struct mesh_polyhedron {
    double (*v)[3];
    int (*t)[3];
    uint16_t *color;
    int nv, nt;
} mesh_polyhedron;
void mesh_polyhedron_free(mesh_polyhedron *p);
/* Solids that touch at an edge or a corner are kept this far apart in a
 * polyhedral part's mesh, of its size (geom_move_apart): a hair, but not so
 * fine that geom_mesh_is_boundary reads the sheets' near-coplanar
 * orientations (the gap squared) as touching. */
#define MESH_PINCH_GAP 1e-5
#define MESH_POLYHEDRAL (-2)

/* Family a holds the rays along axis a.  Its rays are indexed by the other
 * two axes u < v: ray (iu, iv) is number iu + (n[u] + 1) * iv, and its
 * crossings are hit[a][off[a][r] .. off[a][r + 1]), sorted by t, alternating
 * enter / exit starting with an enter (they are the ends of disjoint
 * spans). */
struct mesh_dexels {
    double h;
    double org[3]; /* world position of node (0, 0, 0) */
    int n[3];      /* cells per axis; nodes are 0 .. n[a] */
    size_t *off[3];
    mesh_hit *hit[3];
    size_t nhit[3];
    mesh_palette pal; /* what the crossings' colours mean */
    /* The crossings' patches (mesh_patch_of, without the flag), an
     * open-addressing set of patch_cap slots, 0 empty; curved where two of
     * a patch's crossings had different normals (mark_planar). */
    uint32_t *patch_key;
    uint8_t *patch_curved;
    size_t patch_cap;
    /* The scene and root the rays were cast into (borrowed: the caller
     * keeps the scene while it has the sampling); contouring asks it for
     * exact points on sharp edges (snap.c). */
    const csg_scene *scene;
    int root;
    /* A primitive alone on this grid whose own faces are its mesh
     * (exact_faces.c); MESH_POLYHEDRAL: the exact boundary of the grid's
     * plane-faced part is (poly, polyhedral.c); or -1: the grid is
     * contoured. */
    int32_t exact;
    mesh_polyhedron poly;
    /* The next grid, over a part of the model far from this one's
     * (mesh_dexels_new samples such parts each on its own grid). */
    struct mesh_dexels *next;
};

/* A box of the model sampled on a grid of its own (pieces.c): one
 * operand of the top-level unions alone (a leaf: its primitive, prim) or
 * several (prim -1). */
typedef struct mesh_piece {
    double lo[3], hi[3];
    int32_t prim;
} mesh_piece;

/* Call fn(ud, node, its info) for each operand of node i's top-level
 * unions (nested unions flattened; i itself when it is no union), in
 * order, until fn returns nonzero: that value, or 0 (pieces.c). */
typedef int (*mesh_operand_fn)(void *ud, int32_t node, const csg_scene_node_info *f);
int mesh_top_operands(const csg_scene *s, int32_t i, mesh_operand_fn fn, void *ud);
/* The far-apart parts of root: boxes no two of whose grids (spacing h, or
 * the box's longest side / cells when h <= 0) meet.  Their number (0 for an
 * empty root) and the boxes in *out (free), or -1 when out of memory. */
int mesh_pieces(const csg_scene *s, int root, double h, int cells, mesh_piece **out);
/* The longest side of a piece's box. */
double mesh_piece_longest(const mesh_piece *p);

/* A primitive's corners and triangles, object space: borrowed from the
 * shape, or the box's (corners in box), or made for it (own_v, own_t: a
 * prism's); cw where they wind clockwise seen from outside (a mesh's, as
 * OpenSCAD winds them). */
typedef struct mesh_faces {
    const double (*v)[3];
    const int32_t (*t)[3];
    int nv, nt, cw;
    double box[8][3];
    double (*own_v)[3];
    int (*own_t)[3];
} mesh_faces;
/* Fill f with the faces of a plane-faced shape (box, polytope that knows
 * its triangles, mesh, prism of a region): 1, or 0 when it has none
 * (curved) or out of memory; mesh_faces_free either way. */
int mesh_faces_of(const iv_shape *sh, mesh_faces *f);
void mesh_faces_free(mesh_faces *f);
/* Whether f's triangles bound the solid the rays see (geom_mesh_is_boundary
 * on them counter-clockwise): 1 or 0. */
int mesh_faces_bound(const mesh_faces *f);

/* The exact boundary of the part lo..hi of d's root (its operands of the
 * top-level unions that meet the box) where every primitive of it is
 * plane-faced and the booleans come out a closed mesh that bounds the
 * solid (polyhedral.c): 1 with it in *out (mesh_polyhedron_free), 0 when
 * not, -1 out of memory. */
int mesh_polyhedral(const mesh_dexels *d, const double lo[3], const double hi[3],
                    mesh_polyhedron *out);
/* The same for the top-level operands only[0 .. nonly) (nodes) of the part
 * (all: only NULL), without the check against the grid: 1, 0 or -1. */
int mesh_polyhedral_of(const mesh_dexels *d, const double lo[3], const double hi[3],
                       const int32_t *only, int nonly, mesh_polyhedron *out);
/* The check on the booleans from the rays: p's volume within 2 % and its
 * area times h of the grid's `volume` of the same solid (the grid is exact
 * along each ray and a midpoint rule across: a fraction of a cell's depth
 * over the surface; a piece the booleans kept or lost wrongly is more),
 * and its corners and triangles apart as floats.  1, or 0 with p freed. */
int mesh_polyhedral_agrees(mesh_polyhedron *p, double volume, double h);
/* Where the part lo..hi of grid d is not plane-faced as a whole, its
 * top-level operands in clusters (boxes within MESH_CLUSTER_PAD cells of
 * one another): the clusters that are plane-faced meshed exactly
 * (clusters.c).  1 when some are: d then holds their crossings alone,
 * exact = MESH_POLYHEDRAL and their boundary in poly, and a new grid after
 * it (d->next) the rest's crossings, contoured; 0 when none (d as it
 * was); -1 out of memory. */
int mesh_polyhedral_clusters(mesh_dexels *d, const double lo[3], const double hi[3]);

/* Whether the corners v[0 .. nv) and triangles t[0 .. nt), as a mesh
 * holds them (floats), stay apart and keep their areas: 1 or 0 (also when
 * a corner is not finite, or out of memory). */
int mesh_floats_apart(const double (*v)[3], int nv, const int32_t (*t)[3], int nt);

/* Whether primitive prim can be meshed as its own faces (exact_faces.c):
 * a polytope that knows its triangles, a box, or a polyhedron (written or
 * imported) whose triangles bound its solid (geom_mesh_is_boundary), whose
 * corners stay apart and triangles keep their area as floats. */
int mesh_exact_faces(const csg_scene *s, int32_t prim);
/* The faces of the grids of d whose primitive is meshed so (their exact),
 * appended to m and counted in its exact_nv and exact_nt; 0 or -1 when out
 * of memory. */
int mesh_exact_append(const mesh_dexels *d, mesh *m);
/* A mesh's exact faces set aside while the rest is simplified: detach
 * takes them out of m into *x (0, or -1 when out of memory: m unchanged),
 * attach puts them back at its end and frees x (0 or -1). */
typedef struct mesh_exact_tail {
    float *v;
    int32_t *t; /* indices into v */
    uint16_t *tc;
    int nv, nt;
} mesh_exact_tail;
int mesh_exact_detach(mesh *m, mesh_exact_tail *x);
int mesh_exact_attach(mesh *m, mesh_exact_tail *x);
void mesh_exact_tail_free(mesh_exact_tail *x);

/* Cast the three families on one grid of spacing h around [lo, hi] (the
 * caller's options for threads, root and limits) into a new sampling *out;
 * 0, or an error code with a message (as mesh_dexels_new). */
int mesh_dexels_cast(const csg_scene *s, const mesh_options *o, double h, const double lo[3],
                     const double hi[3], mesh_dexels **out, char *err, size_t errlen);

/* A 64-bit key's hash (MurmurHash3's finaliser, half of it), for the
 * open-addressing maps of contour.c and refine.c. */
static inline uint64_t mesh_hash_mix(uint64_t k)
{
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    return k;
}

/* How far (in cells) contour vertices keep from grid nodes, edges and
 * faces (contour.c).  It bounds the smallest triangle area from below
 * (about EPS²·h²/2); at 1/256 even a model far from the origin keeps EPS·h
 * hundreds of float ulps wide.  A vertex held so far off its surface or
 * its sharp edge tilts the slivers around it at any angle, which the
 * simplifier would read as sharp edges: edge crossings go back onto their
 * tangent planes, and no face point is drawn beside a crossing its edge
 * runs through (contour.c); the simplifier asks the exact surfaces before
 * it calls an edge sharp (simplify.c, on_edge). */
#define MESH_CONTOUR_EPS (1.0 / 256)

/* A patch: one face of one primitive (a plane of a polyhedron, a sphere,
 * a cylinder's side), named by a nonzero hash of the primitive and its
 * part; the sampling sets MESH_PATCH_PLANAR on those whose every crossing
 * has one normal.  Two crossings on two plane patches whose normals differ
 * lie either side of a sharp edge, however slight its angle (a polygon's
 * facets at $fn = 30 meet at 12°); two curved patches may join smoothly
 * (a revolved profile's arcs). */
#define MESH_PATCH_PLANAR 0x80000000u
#define MESH_COS_PATCH 0.99985 /* cos 1° */
static inline uint32_t mesh_patch_of(int32_t prim, uint16_t part)
{
    return ((uint32_t)mesh_hash_mix((uint64_t)(uint32_t)prim << 16 | part) & ~MESH_PATCH_PLANAR) |
           1;
}

/* The spacing of the grid of d (or of a later one: d->next...) whose box,
 * a cell larger all round, holds p; d->h where none does. */
double mesh_dexels_h_at(const mesh_dexels *d, const double p[3]);

/* Patch p (mesh_patch_of) flagged MESH_PATCH_PLANAR when the grids of
 * sampling d (d and those after it) hold it as a plane (dexels.c). */
uint32_t mesh_patch_flagged(const mesh_dexels *d, uint32_t p);

/* Whether surfaces of patches pa and pb, their normals' cosine c, meet at a
 * sharp edge however slight: two planes of different patches more than 1°
 * apart (the feature angle rules the rest). */
static inline int mesh_planes_crease(uint32_t pa, uint32_t pb, double c)
{
    return pa != pb && (pa & pb & MESH_PATCH_PLANAR) && c < MESH_COS_PATCH;
}

/* An open-addressing map from nonzero 64-bit keys to vertex numbers
 * (contour.c): the face points by their segment's ends, every vertex by
 * its place. */
typedef struct mesh_fmap {
    uint64_t *key; /* 0 = empty */
    int32_t *val;
    size_t cap, n;
} mesh_fmap;

/* key's value slot, added (*fresh set, the value unset) when absent; NULL
 * when out of memory. */
int32_t *mesh_fmap_slot(mesh_fmap *m, uint64_t key, int *fresh);
/* Whether key is in m. */
int mesh_fmap_has(const mesh_fmap *m, uint64_t key);
/* 64 bits that tell the float positions of vertices apart (+0 and -0
 * alike, as a reader welding by position sees them); never 0. */
uint64_t mesh_pos_key(const double p[3]);

/* The other two axes of a, in increasing order. */
static inline void mesh_axes_other(int a, int *u, int *v)
{
    *u = a == 0 ? 1 : 0;
    *v = a == 2 ? 1 : 2;
}

struct mesh {
    float *v;
    int32_t *t;
    int nv, nt;
    int capv, capt;
    /* With colours (npal > 0): triangle i has colour tc[i], 1 .. npal
     * (pal[tc[i] - 1]), or 0 (none given). */
    uint16_t *tc;
    int captc;
    float (*pal)[4];
    int npal;
    /* The last exact_nv vertices and exact_nt triangles are primitives' own
     * faces (mesh_exact_append): exact, and left as they are. */
    int exact_nv, exact_nt;
};

/* Vertex i of m, in doubles. */
static inline void mesh_vertex_at(const mesh *m, int32_t i, double p[3])
{
    for (int c = 0; c < 3; c++)
        p[c] = m->v[3 * (size_t)i + c];
}

/* x as a vertex of a mesh holds it: each coordinate rounded to float (the
 * build keeps GCC 12's SLP vectorizer from dropping this; see Makefile). */
void mesh_round_to_float(double x[3]);

/* The tri_normal3 of triangle t of m (not unit: twice its area long). */
void mesh_triangle_normal(const mesh *m, int32_t t, double n[3]);

/* The triangles [t0, m->nt) around each vertex: fan[start[v] .. start[v +
 * 1]) for vertex v (both free by the caller); 0, or -1 when out of memory
 * (nothing to free). */
int mesh_vertex_fans(const mesh *m, int32_t t0, int32_t **start, int32_t **fan);

/* Each half-edge x = 3·(t − t0) + k of triangles [t0, m->nt) (corner k to
 * corner k + 1) paired with its twin running the other way in opp[x] (3·(nt
 * − t0) entries), or -1 where it has none; 0, or -1 when out of memory. */
int mesh_half_twins(const mesh *m, int32_t t0, int32_t *opp);

/* Move vertex v to `to`, unless that turns one of the nf triangles fan
 * around it by acos(min_cos) or more from its normal now, or leaves one
 * with twice its area squared at most min2 (a fan of more than 64: never);
 * 1 when moved. */
int mesh_vertex_move(mesh *m, int32_t v, const int32_t *fan, int nf, const double to[3],
                     double min_cos, double min2);

/* Append a vertex / a triangle (of colour `color`, kept when the mesh has
 * colours); return its index, or -1 when out of memory or past INT32_MAX. */
int mesh_push_vertex(mesh *m, double x, double y, double z);
int mesh_push_triangle(mesh *m, int32_t a, int32_t b, int32_t c, uint16_t color);
/* Give m (still without triangles) the colours of palette p; 0 or -1 (out
 * of memory). */
int mesh_set_palette(mesh *m, const mesh_palette *p);

/* The minimum-norm least-squares solution x of a x = b for a symmetric 3×3
 * a (destroyed), eigenvalues below cut times the largest dropped
 * (contour.c). */
void mesh_qef_solve(double a[3][3], const double b[3], double cut, double x[3]);

/* Contour vertices moved onto the exact surface (snap.c). */
typedef struct mesh_snapper {
    const mesh_dexels *d;
    double cos_feature;
    iv_arena *arena; /* NULL: the sampling has no scene; nothing moves */
} mesh_snapper;

/* 0, or -1 when out of memory. */
int mesh_snapper_init(mesh_snapper *sn, const mesh_dexels *d, double cos_feature);
void mesh_snapper_free(mesh_snapper *sn);
/* The crossing of the line x + t·n, |t| <= reach (n a unit vector), nearest
 * x whose normal is within acos(min_cos) of n: into p and pn, 1; 0 when
 * there is none (or the sampling has no scene). */
int mesh_snap_probe(mesh_snapper *sn, const double x[3], const double n[3], double reach,
                    double min_cos, double p[3], double pn[3]);
/* mesh_snap_probe, the crossing on patch `patch` (0: any), its patch into
 * *found (not NULL). */
int mesh_snap_probe_patch(mesh_snapper *sn, const double x[3], const double n[3], double reach,
                          double min_cos, uint32_t patch, double p[3], double pn[3],
                          uint32_t *found);
/* mesh_snap_probe (any normal), with the crossing's patch (unflagged)
 * into *found and the surface it lies on as a quadric into q
 * (csg_scene_quadric); 0 when there is none. */
int mesh_snap_probe_quadric(mesh_snapper *sn, const double x[3], const double n[3], double reach,
                            double p[3], double pn[3], uint32_t *found, iv_quadric *q);
/* Whether x lies inside the solid (a short ray along axis a through it):
 * 1 or 0; -1 when the sampling has no scene or the ray fails. */
int mesh_snap_inside(mesh_snapper *sn, const double x[3], int a);
/* The exact normals of the contour's vertices that are ray crossings (the
 * others: 0, 0, 0), and which vertices lie on a sharp edge (put there by
 * mesh_snap), by vertex index; all NULL and cap 0 to start, then
 * mesh_vnormals_free. */
typedef struct mesh_vnormals {
    float (*n)[3];
    uint8_t *edge;
    uint32_t *patch; /* the crossing's patch (mesh_hit.patch); 0: none */
    size_t cap;
} mesh_vnormals;
/* 0, or -1 when out of memory. */
int mesh_vnormal_set(mesh_vnormals *vn, int32_t v, const double n[3], int on_edge, uint32_t patch);
void mesh_vnormals_free(mesh_vnormals *vn);
/* Move the vertices of triangles [t0, m->nt) of m (made on sampling grid
 * sn->d) that have no normal in vn and lie off the exact surface onto it,
 * then split the edges whose midpoints lie off it where it bends, each by
 * more than a hundredth of a cell or (tol > 0) half of tol, never to a
 * place in pos (every vertex by mesh_pos_key; the new places are added)
 * (refine.c); vn gets the moved and new vertices' normals.  0 or -1 when
 * out of memory. */
int mesh_refine_edges(mesh *m, int t0, double tol, mesh_snapper *sn, mesh_vnormals *vn,
                      mesh_fmap *pos);
/* Put m's chords across the edges and corners of plane faces on them:
 * vertices a little off a crease moved onto it, knots of short edges
 * collapsed, edges whose ends lie on two plane faces (and no common one)
 * flipped or split on the crease where those meet, and triangles whose
 * corners lie on three given the point where they meet, where rays find
 * those points on the surface (sn); *splits counts the changes (crease.c).
 * 0 or -1 when out of memory. */
int mesh_split_creases(mesh *m, mesh_snapper *sn, int *splits);
/* Flip the edges of triangles [t0, m->nt) of m (grid spacing h) whose two
 * triangles lie back to back, where that leaves fewer such edges
 * (unfold.c); 0 or -1 when out of memory. */
int mesh_unfold(mesh *m, int t0, double h);
/* Flip the edges of triangles [t0, m->nt) of m (grid spacing h; vn its
 * vertices' exact normals and sharp-edge flags) about which two triangles
 * bend by 30° more than the exact normals of their corners part, where
 * the flip bends by 30° less and turns neither new triangle away from its
 * corners' normals (unfold.c); 0 or -1 when out of memory. */
int mesh_unbend(mesh *m, int t0, double h, const mesh_vnormals *vn);
/* Flip the long edge of each sliver of m (grid spacing h) whose corner lies
 * within a tenth of that edge's length of its middle, where the surface
 * about it is smooth (no neighbour turned 20° or more) and the flip leaves
 * no sliver and a new edge whose middle lies nearer the exact surface (sn)
 * than the old one's (unfold.c); 0 or -1 when out of memory. */
int mesh_unsliver(mesh *m, mesh_snapper *sn, double h);
/* Take away the vertices of m whose triangles all lie in one plane (each
 * of m's vertices within eps of it) and have one colour, each collapsed
 * into a neighbour whose fan over its ring turns no triangle over, in
 * rounds until none is left that can go (flatten.c); the surface stays
 * within eps of m's, closed, 2-manifold and outward.  0, or -1 when out of
 * memory (m then holds some of the collapses). */
int mesh_flatten(mesh *m, double eps);
/* Simplify m in place by edge collapses (simplify.c) while every vertex and
 * sharp edge's midpoint of m stays within tol of the triangles that replace
 * it where m is curved, within edge_tol on flat faces, on sharp edges and
 * near triangles with a corner on one: still closed, 2-manifold and outward, every vertex one of
 * m's own.  With a snapper (sn, else NULL) the sharp edges' midpoints are
 * first put on the exact edges.  Slabs of the mesh are simplified on up to `threads` threads,
 * then the whole; the result does not depend on the number of threads.
 * Returns 0, or -1 with a message (out of memory; m is then unchanged). */
int mesh_simplify(mesh *m, double tol, double edge_tol, mesh_snapper *sn, int threads, char *err,
                  size_t errlen);

/* Move the smooth vertices of mesh m, simplified to within `bound` of the
 * surface, out by half the largest sag of their triangles (at most half
 * the bound), measured by rays up to four bounds from them; a vertex whose
 * triangles lie on plane patches alone only where their sags span at most
 * the bound (balance.c); 0 or -1 when out of memory. */
int mesh_balance(mesh *m, mesh_snapper *sn, double bound);
/* Split the triangles of m's smooth parts that stray from the exact
 * surface by more than tol, measured by rays at seven points each (on up
 * to `threads` threads), on their longest edges, and the sides elsewhere
 * that cut across a sharp edge by more than tol on it; flip a side of
 * those that stray and cannot be split where that brings them nearer; in
 * rounds (tighten.c).  0 or -1 when out of memory. */
int mesh_tighten(mesh *m, mesh_snapper *sn, double tol, int threads);
/* Move x (a vertex placed from the ns samples sp, with normals nrm and
 * patches patch (mesh_hit.patch; NULL: not known), of its cell) onto the
 * exact surfaces those samples lie on — up to three: the surface, a sharp
 * edge, a corner — as nearly as the box [lo, hi] allows, the coordinate
 * `fixed` (an axis, or -1) kept.  Samples lie on two surfaces when their
 * normals part by more than the feature angle, or (given patches) they lie
 * on two plane patches more than 1° apart (mesh_planes_crease).  Left where
 * it is when it fits the surfaces there better, or the samples hold more
 * than three surfaces (0); else the number of surfaces. */
int mesh_snap(mesh_snapper *sn, const double (*sp)[3], const double (*nrm)[3],
              const uint32_t *patch, int ns, int fixed, const double lo[3], const double hi[3],
              double x[3]);

#endif

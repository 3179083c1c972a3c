/*
 * crease.h — what the crease rules share (src/mesh only): the planes of
 * plane faces met so far, the mesh as the rules see it in a pass, and the
 * helpers both crease.c (chords, knots) and crease_cap.c (caps across an
 * acute crease) use.  See crease.c.
 */
#ifndef RAYSCAD_MESH_CREASE_H
#define RAYSCAD_MESH_CREASE_H

#include "dexels.h"

#include <stddef.h>
#include <stdint.h>

#define ON 1e-4         /* cells: a vertex this near a plane lies on it (see near_planes) */
#define KNOT_R 3.0      /* cells: see untie_corner() */
#define MAX_PLANES 8    /* candidates per edge or triangle */
#define KNOT_PLANES 16  /* candidates about a knot (fan_knot) */
#define COS_APART 0.985 /* planes whose normals part by less (10°) are left to the simplifier */

typedef struct plane {
    double n[3], d; /* n·x = d */
} plane;

typedef struct crease_mesh {
    mesh *m;
    mesh_snapper *sn;
    mesh_fmap pos;      /* the vertex at each place in use, -1 at one left */
    double h, min2;     /* the cell; twice a triangle's area squared, at least */
    plane *pl;          /* the planes met so far */
    int32_t npl, cap;   /* of pl */
    mesh_fmap by_patch; /* patch -> index into pl */
    int32_t *tp;        /* each triangle's plane (index into pl), -1: none, -2: not looked for */
    size_t tp_cap;
    uint8_t *hot; /* vertices whose surroundings changed (all, at first), or REFUSED */
    uint32_t *vmark, *tmark, mark_now; /* fan_knot's marks on vertices and triangles */
    uint64_t *tried;   /* by vertex: the corner (place) its knot last tried this pass */
    mesh_fmap crowded; /* the corners (places) whose knots were too big this pass */
    int32_t nv0;       /* the vertices as the pass began */
    size_t hot_cap;
    int32_t *start, *fan;    /* the triangles around each vertex, as the pass began */
    int32_t *opp;            /* each half-edge's twin, as the pass began */
    uint8_t *used;           /* triangles changed this pass */
    uint8_t *ends;           /* vertices a flip joined this pass */
    uint8_t *known;          /* on_a_plane's answers this pass: 0 not asked, 1 no, 2 yes */
    size_t nknown;           /* of known: 0 while vertices still move */
    int gone;                /* triangles emptied this pass */
    struct crease_cap *capk; /* crease_unzip_cap's (large) cap */
} crease_mesh;

/* A vertex at x (float), not where one is; its number, -1 when one is
 * there, -2 when out of memory. */
int32_t crease_add_vertex(crease_mesh *c, const double x[3]);
/* The planes under the triangles around vertices vs (nv), distinct, into
 * out (MAX_PLANES at most); their count. */
int crease_candidates(const crease_mesh *c, const int32_t *vs, int nv, const plane **out);
/* Where planes a, b and c meet, into x; 0 when they nearly share a line. */
int crease_corner(const plane *a, const plane *b, const plane *c, double x[3]);
/* Triangle t's corners with vertex v read as w, into tv and p; 0 when two
 * of them are then one vertex. */
int crease_corners_as(const crease_mesh *c, int32_t t, int32_t v, int32_t w, int32_t tv[3],
                      double p[3][3]);
/* A point of the line where planes a and b meet into p0, its direction
 * (not unit) into e; 0 when they part by less than COS_APART. */
int crease_line(const plane *a, const plane *b, double p0[3], double e[3]);
/* Whether the triangle tv (corners at p) lies on a plane of pl (np) its
 * corners share, with area, facing like it. */
int crease_fits(const crease_mesh *c, const int32_t tv[3], double p[3][3], const plane *const *pl,
                int np);
/* Whether the triangle p, q, r has area and faces like the first of the
 * planes of bits `shared` of pl (like n where there is none). */
int crease_half_ok(const plane *const *pl, unsigned shared, const double p[3], const double q[3],
                   const double r[3], const double n[3], double min2);
/* Vertex v leaves its place (moved or collapsed away); 0 or -1. */
int crease_leave_place(crease_mesh *c, int32_t v);
/* Whether triangle t has corner v. */
int crease_has(const mesh *m, int32_t t, int32_t v);
/* Whether x, where the n (2 or 3) planes pl meet, lies on the surface. */
int crease_meets_on_surface(crease_mesh *c, const double x[3], const plane *const *pl, int n);
/* Whether vertex v lies on the plane under one of its triangles. */
int crease_on_a_plane(crease_mesh *c, int32_t v);
/* Which of the planes pl (np) vertex v lies on, as bits. */
unsigned crease_on_planes(const crease_mesh *c, int32_t v, const plane *const *pl, int np);
/* Whether x lies on the surface: a ray through it along n finds it there. */
int crease_on_surface(crease_mesh *c, const double x[3], const double n[3]);
/* The slot of place x in c->pos: the vertex there, or -1; NULL when out
 * of memory. */
int32_t *crease_place(crease_mesh *c, const double x[3]);
/* Which of the planes pl (np) x lies within `cells` of (or of rounding),
 * as bits. */
unsigned crease_planes_near(const crease_mesh *c, const double x[3], const plane *const *pl, int np,
                            double cells);
/* Whether a triangle at p lies on the surface (rays along its normal
 * through five points of it). */
int crease_lies_on_surface(crease_mesh *c, double p[3][3]);

/* Unzip the cap across an acute crease that triangle t belongs to
 * (crease_cap.c); 1 when done, 0 when not, -1 when out of memory. */
int crease_unzip_cap(crease_mesh *c, int32_t t);

#endif

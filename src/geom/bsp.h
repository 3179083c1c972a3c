/*
 * bsp.h — booleans of polyhedral solids given by their boundary polygons,
 * through BSP trees (Naylor, Amanatides and Thibault, "Merging BSP trees
 * yields polyhedral set operations", 1990, in the form of Evan Wallace's
 * csg.js).  hull() and minkowski() take the vertices and faces of a
 * boolean's result from here; the pictures never do (rays meet the
 * operands exactly).
 *
 * The result is a set of convex polygons that covers the boundary of the
 * result exactly (up to the plane tolerance); it may hold T-junctions, so
 * it is a surface to take points and faces from, not a mesh to export.
 */
#ifndef RAYSCAD_GEOM_BSP_H
#define RAYSCAD_GEOM_BSP_H

/* Convex planar polygons, each counter-clockwise seen from outside the
 * solid they bound: polygon i is v[start[i] .. start[i + 1]), and carries
 * tag[i] (whose face it is: the booleans keep it on every piece). */
typedef struct geom_polys {
    double (*v)[3];
    int *start; /* n + 1 entries once a polygon is added */
    int *tag;   /* n entries */
    int n, nv, capv, capn;
} geom_polys;

void geom_polys_free(geom_polys *p);
/* Appends polygon v[0 .. k) (k >= 3) with tag 0 / with `tag`.  Returns 0,
 * or -1 out of memory. */
int geom_polys_add(geom_polys *p, const double (*v)[3], int k);
int geom_polys_add_tagged(geom_polys *p, const double (*v)[3], int k, int tag);
/* Appends every polygon of q.  Returns 0, or -1 out of memory. */
int geom_polys_append(geom_polys *p, const geom_polys *q);

/* Whether the boxes of a's and b's points meet (touching counts): where
 * they do not, no boolean of the two need cut anything. */
int geom_polys_meet(const geom_polys *a, const geom_polys *b);

typedef enum { GEOM_BSP_UNION, GEOM_BSP_INTERSECTION, GEOM_BSP_DIFFERENCE } geom_bsp_op;

enum { GEOM_BSP_NO_MEMORY = -1, GEOM_BSP_TOO_MUCH = -2 };

/* The boundary of a op b into *out (emptied first).  *work is the number
 * of polygon-plane tests still allowed (decremented): when it runs out the
 * operation stops with GEOM_BSP_TOO_MUCH.  Returns 0 or a GEOM_BSP_ code;
 * *out is empty on failure. */
int geom_bsp_boolean(geom_bsp_op op, const geom_polys *a, const geom_polys *b, long *work,
                     geom_polys *out);

#endif

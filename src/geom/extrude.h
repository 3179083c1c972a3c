/*
 * extrude.h — linear_extrude with twist or scale, as the very polyhedron
 * OpenSCAD 2021.01 builds (extrude.c).
 */
#ifndef RAYSCAD_GEOM_EXTRUDE_H
#define RAYSCAD_GEOM_EXTRUDE_H

#include "../intervals/intervals.h"

typedef struct geom_extrusion {
    double h1, h2;   /* z of the bottom and of the top */
    double twist;    /* degrees: the top is turned by -twist */
    double scale[2]; /* the top's scale in x and y (>= 0, finite) */
    int slices;      /* layers between bottom and top, >= 1 */
} geom_extrusion;

/* Calc::get_helix_slices, get_conical_helix_slices and get_diagonal_slices
 * of OpenSCAD 2021.01: the slice count e's twist and scale default to, from
 * the largest squared radius of the outline's vertices (max_r2), the
 * largest squared distance a vertex moves between bottom and top scale
 * (max_d2) and $fn, $fa, $fs.  A twist needs at least one slice per 120°;
 * at most 100000. */
int geom_extrusion_slices(const geom_extrusion *e, double max_r2, double max_d2, double fn,
                          double fa, double fs);

/* The closed mesh of region r (borrowed) extruded as e says, in *out
 * (which then holds its only reference).  Returns 0, or -1 when out of
 * memory or when nothing is left (every face degenerate). */
int geom_extrusion_mesh(const geom_extrusion *e, const iv_region *r, iv_shape *out);

#endif

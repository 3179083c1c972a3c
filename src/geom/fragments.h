/*
 * fragments.h — OpenSCAD 2021.01's rule for how many straight pieces a
 * circle, a sphere's ring or an arc is made of ($fn, $fa, $fs), once for
 * every caller: the builtin modules, the DXF reader, extrusions.
 */
#ifndef RAYSCAD_GEOM_FRAGMENTS_H
#define RAYSCAD_GEOM_FRAGMENTS_H

/* OpenSCAD's GRID_FINE: a circle of smaller radius has 3 fragments. */
#define GEOM_GRID_FINE 0.00000095367431640625

/* The most fragments of any circle: OpenSCAD has no cap, but a polytope
 * of more faces than this is refused anyway. */
enum { GEOM_MAX_FRAGMENTS = 100000 };

/* Calc::get_fragments_from_r of OpenSCAD 2021.01: 3 below GEOM_GRID_FINE
 * (or for a NaN radius) and for an infinite or NaN fn; fn itself (at
 * least 3) when positive; else ceil(max(min(360 / fa, 2πr / fs), 5)), with
 * fa and fs raised to 0.01.  Capped at GEOM_MAX_FRAGMENTS. */
int geom_fragments(double r, double fn, double fa, double fs);

#endif

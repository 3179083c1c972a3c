/*
 * hull3d.h — the 3D convex hull that hull(), minkowski() and
 * OpenSCAD-faceted spheres and cylinders build their polytopes with.
 */
#ifndef RAYSCAD_GEOM_HULL3D_H
#define RAYSCAD_GEOM_HULL3D_H

#include "../intervals/intervals.h"

enum {
    GEOM_HULL_FLAT = -1,      /* no volume (fewer than 4 points off one plane) */
    GEOM_HULL_BAD_INPUT = -2, /* a coordinate is not finite */
    GEOM_HULL_NO_MEMORY = -3,
    GEOM_HULL_TOO_MANY = -4 /* more faces than a polytope holds (65536) */
};

/* The convex hull of the n points P (borrowed) as a polytope in *s, which
 * then holds the only reference: the same solid the incremental hull makes — the
 * same tolerance, points within it of a face count as inside — in
 * O(n log n) expected time instead of O(n · faces).  Returns 0, or one of
 * the GEOM_HULL_ codes (nothing made). */
int geom_hull3d(iv_shape *s, const double (*P)[3], int n);

#endif

/*
 * hull3d_internal.h — private to src/geom: what the convex hull's two
 * algorithms share (hull3d_incremental.c).
 */
#ifndef RAYSCAD_GEOM_HULL3D_INTERNAL_H
#define RAYSCAD_GEOM_HULL3D_INTERNAL_H

#include "../intervals/intervals.h"

/* The tolerance of a convex hull of P[0..n): 1e-11 of the larger of the
 * points' extent and their largest coordinate (distances below it count as
 * on a plane: a few thousand ulps of the coordinates, far above the
 * rounding of a plane test, far below any feature OpenSCAD's grid keeps).
 * Returns 0, or -1 when a coordinate is not finite. */
int geom_hull_eps(const double (*P)[3], int n, double *eps);

/* The tetrahedron a convex hull of P[0..n) starts from: the point of least
 * x, the point farthest from it, the farthest from their line and the
 * farthest from their plane (ids, in that order), and its four faces t[k]
 * wound counter-clockwise seen from outside.  Returns 0, or -1 when the
 * points lie within eps of a line or a plane. */
int geom_hull_tetrahedron(const double (*P)[3], int n, double eps, int ids[4], int t[4][3]);

/* The convex hull of n points as a polytope by the plain incremental
 * algorithm, O(n · faces).  Returns 0, or -1 when the hull is flat or
 * empty, or out of memory. */
int geom_hull3d_incremental(iv_shape *s, const double (*pts)[3], int n);

#endif

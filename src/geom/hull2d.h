/*
 * hull2d.h — the convex hull of points in the plane, for hull() of 2D
 * children.
 */
#ifndef RAYSCAD_GEOM_HULL2D_H
#define RAYSCAD_GEOM_HULL2D_H

/* The hull of the xy of the n points P (sorted in place; z ignored),
 * counter-clockwise into H, which has room for n + 1 points; returns its
 * vertex count (points on an edge are dropped). */
int geom_hull2d(double (*P)[3], int n, double (*H)[2]);

#endif

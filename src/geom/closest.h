/*
 * closest.h — the distance from a point to a triangle.
 */
#ifndef RAYSCAD_GEOM_CLOSEST_H
#define RAYSCAD_GEOM_CLOSEST_H

/* The squared distance from p to triangle abc (any orientation; a
 * degenerate one is its segment or point), from the closest point found
 * by Voronoi regions (Ericson, Real-Time Collision Detection, 5.1.5). */
double geom_triangle_dist2(const double p[3], const double a[3], const double b[3],
                           const double c[3]);

#endif

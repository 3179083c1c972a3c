/*
 * trapezoid.h — a 2D region (closed paths, even-odd rule) cut into convex
 * pieces: the trapezoids between consecutive vertex heights, each bounded
 * left and right by the region's edges.  The caps of prisms and of
 * revolved profiles are built from them where a boolean needs convex
 * faces (bsp.h).
 */
#ifndef RAYSCAD_GEOM_TRAPEZOID_H
#define RAYSCAD_GEOM_TRAPEZOID_H

/* Calls emit with each trapezoid (3 or 4 corners, counter-clockwise,
 * repeated corners dropped) of the region whose path i is
 * P[start[i] .. start[i + 1]).  Returns 0, or -1 when out of memory or
 * when emit returns non-zero. */
int geom_trapezoids(const double (*P)[2], const int *start, int npaths,
                    int (*emit)(void *ud, const double (*q)[2], int k), void *ud);

#endif

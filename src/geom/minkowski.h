/*
 * minkowski.h — the 3D Minkowski sum of convex parts, as minkowski() builds
 * it: the sum distributes over union, and the sum of two convex sets is the
 * convex hull of the sums of their points.  An operand is a union of convex
 * parts, each given by its points.
 */
#ifndef RAYSCAD_GEOM_MINKOWSKI_H
#define RAYSCAD_GEOM_MINKOWSKI_H

/* A convex part: its points (owned). */
typedef struct geom_convex {
    double (*p)[3];
    int n;
} geom_convex;

/* A union of convex parts; {NULL, 0, 0} is the empty one. */
typedef struct geom_convex_set {
    geom_convex *v;
    int n, cap;
} geom_convex_set;

void geom_convex_set_free(geom_convex_set *s);
/* Appends an empty part with room for n points; NULL when out of memory. */
geom_convex *geom_convex_set_add(geom_convex_set *s, int n);

/* Appends to out the hull of all sums p + q of a's and b's points (its
 * vertices); a flat hull, or one that could not be made, adds nothing.
 * Returns -1 when out of memory for the part, else 0. */
int geom_minkowski_pair(const geom_convex *a, const geom_convex *b, geom_convex_set *out);

/* 1 when each of the n points is a vertex of their convex hull. */
int geom_points_convex(const double (*V)[3], int n);
/* 1 when the closed polygon turns one way only (collinear points allowed). */
int geom_polygon_convex(const double (*V)[2], int n);

#endif

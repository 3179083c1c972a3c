/*
 * vec3.h — the few 3-vector operations the geometry code shares, and the
 * plane of a triangle.  Header-only (static inline); doubles throughout.
 */
#ifndef RAYSCAD_VEC3_H
#define RAYSCAD_VEC3_H

#include <math.h>

static inline double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void sub3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[0] - b[0];
    o[1] = a[1] - b[1];
    o[2] = a[2] - b[2];
}

static inline void cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* a · (b × c): six times the signed volume of the tetrahedron (0, a, b, c). */
static inline double triple3(const double a[3], const double b[3], const double c[3])
{
    double x[3];
    cross3(b, c, x);
    return dot3(a, x);
}

/* The normal of triangle a, b, c (counter-clockwise seen from the side it
 * points to), as long as twice the triangle's area. */
static inline void tri_normal3(const double a[3], const double b[3], const double c[3], double n[3])
{
    double u[3], v[3];
    sub3(b, a, u);
    sub3(c, a, v);
    cross3(u, v, n);
}

/* The plane through P[a], P[b], P[c] (counter-clockwise seen from the side
 * n points to): unit normal n and offset d = n·P[a]; -1 when the triangle
 * has no area.  The convex hulls (polytope.c, src/scad/hull3d.c) both take
 * their faces' planes from here, so the same points give bitwise the same
 * planes in either. */
static inline int vec3_plane(const double (*P)[3], int a, int b, int c, double n[3], double *d)
{
    tri_normal3(P[a], P[b], P[c], n);
    double l = sqrt(dot3(n, n));
    if (!(l > 0)) return -1;
    for (int k = 0; k < 3; k++)
        n[k] /= l;
    *d = dot3(n, P[a]);
    return 0;
}

#endif

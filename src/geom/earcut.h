/*
 * earcut.h — a polygon with holes cut into triangles by ear clipping, the
 * holes first bridged into the outline (Eberly, "Triangulation by Ear
 * Clipping", 2002; as mapbox's earcut does).
 */
#ifndef RAYSCAD_GEOM_EARCUT_H
#define RAYSCAD_GEOM_EARCUT_H

/* The polygon whose outline is ring 0 and whose holes are rings 1 ..
 * nrings - 1, ring r being the points P[ring[start[r] .. start[r + 1])]
 * (P borrowed: indices into it, as a mesh's vertices are), cut into
 * triangles of those indices, counter-clockwise, into *tri (the caller
 * frees it).  The outline must run counter-clockwise, each hole clockwise,
 * inside it and apart from the others; a bridge repeats two indices, so
 * the triangles' edges pair up as a closed mesh's do.  Returns the number
 * of triangles, or -1 when out of memory, when a ring has fewer than three
 * points or the points number more than 20000, or when the clipping finds
 * no ear (rings that cross; nothing is written). */
int geom_earcut(const double (*P)[2], const int *ring, const int *start, int nrings,
                int (**tri)[3]);

/* Even-odd test of (x, y) against the closed path P[0 .. n). */
int geom_path_contains(const double (*P)[2], int n, double x, double y);

/* A 2D region — closed paths P[start[i] .. start[i + 1]) under the
 * even-odd rule, nested but apart — cut into triangles of its points'
 * indices, counter-clockwise, into *tri (the caller frees it): each outer
 * path (inside an even number of others) with the holes right inside it,
 * whatever way the paths run.  Returns the number of triangles, or -1
 * as geom_earcut (paths that cross or touch). */
int geom_region_triangles(const double (*P)[2], const int *start, int npaths, int (**tri)[3]);

/* The closed triangle mesh of the prism over that region from z0 to z1
 * (z0 < z1): point i of the region is vertex i at z0 and vertex n + i at
 * z1 (n points), *v their 2n positions; the caps the region's triangles,
 * each edge of a path a quad of two triangles; counter-clockwise seen from
 * outside.  *v and *tri belong to the caller.  Returns the number of
 * triangles, or -1 as geom_region_triangles. */
int geom_prism_mesh(const double (*P)[2], const int *start, int npaths, double z0, double z1,
                    double (**v)[3], int (**tri)[3]);

#endif

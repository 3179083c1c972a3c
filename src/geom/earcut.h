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

#endif

/*
 * heightmap.h — the polyhedron surface() builds of a heightmap: the very
 * one of OpenSCAD 2021.01's SurfaceNode::createGeometry, each grid cell four
 * triangles meeting at its centre (at the mean of the corner heights), four
 * side walls down to a flat bottom at the map's base, the bottom one polygon.
 */
#ifndef RAYSCAD_GEOM_HEIGHTMAP_H
#define RAYSCAD_GEOM_HEIGHTMAP_H

#include "../intervals/intervals.h"

/* w × h heights (owned by the caller), row 0 at y = 0; base is the bottom's
 * height, OpenSCAD 2021.01's min(0, lowest - 1) for both kinds of file. */
typedef struct geom_heightmap {
    double *z;
    int w, h;
    double base;
} geom_heightmap;

/* The polyhedron of m (at the origin's corner, or centred on it in x and y)
 * as a mesh in *out, its faces in OpenSCAD's order, each reversed into
 * iv_shape_mesh's clockwise winding.  Returns 0, or -1 (too large, or out of
 * memory). */
int geom_heightmap_mesh(const geom_heightmap *m, int center, iv_shape *out);

#endif

/*
 * pinch.h — a closed triangle mesh whose solids touch along an edge or at
 * a corner (two cubes edge to edge, a checkerboard) made 2-manifold.
 *
 * The exact boundary of such a union has four faces (or more) at an edge
 * and two fans (or more) about a vertex, as openscad's CGAL writes it, and
 * a reader that welds by position sees no 2-manifold there.  geom_unpinch
 * pairs the faces at each such edge so that the solids stay apart (each
 * face with its neighbour across a wedge of solid) and gives every fan
 * about a vertex a vertex of its own; geom_move_apart then moves the copies
 * of a position a hair into their own solids, so that they stay apart as
 * floats too.
 */
#ifndef RAYSCAD_GEOM_PINCH_H
#define RAYSCAD_GEOM_PINCH_H

enum { GEOM_PINCH_NO_MEMORY = -1, GEOM_PINCH_CANNOT = -2 };

/* T[0 .. nt) over *V (*nv vertices, counter-clockwise from outside, every
 * edge as often one way as the other): the faces at an edge of more than
 * two paired around it, solid wedge by solid wedge, and each fan about a
 * vertex after the first given a copy of the vertex (appended to *V, which
 * is realloc'd; T's corners renumbered).  Returns the number of copies
 * made, GEOM_PINCH_CANNOT where an edge's faces do not alternate (an edge
 * once more one way than the other, two faces on one side of an edge in
 * one plane) or a vertex has a corner outside every fan, or
 * GEOM_PINCH_NO_MEMORY (nothing changed then). */
int geom_unpinch(double (**V)[3], int *nv, int (*T)[3], int nt);

/* Every vertex of V[0 .. nv) that shares its position with another moved
 * by `gap` into its own solid: against its fan's angle-weighted normal.
 * 0, GEOM_PINCH_CANNOT where a fan's normals cancel, or
 * GEOM_PINCH_NO_MEMORY. */
int geom_move_apart(double (*V)[3], int nv, const int (*T)[3], int nt, double gap);

#endif

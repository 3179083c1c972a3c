/*
 * mesh_boundary.h — whether a triangle mesh is exactly the boundary of the
 * solid it encloses, so that its own triangles may stand for that solid.
 */
#ifndef RAYSCAD_GEOM_MESH_BOUNDARY_H
#define RAYSCAD_GEOM_MESH_BOUNDARY_H

/* Whether the triangles tri[0 .. nt) over v[0 .. nv) (borrowed;
 * counter-clockwise seen from outside) are exactly the boundary of the
 * solid the nonzero rule makes of them: every edge used once each way, each
 * vertex's triangles one fan, no shell sharing a vertex with another, no
 * triangle without area, no two triangles meeting but at the corners and
 * edges they share, and the winding number 0 in front of every shell
 * (nested shells wound alike fill each other: the inner one is no
 * boundary; a void wound inward is).  1 when so, 0 when not or when it
 * would take more than about 64 pair tests a triangle to tell (nothing
 * written), -1 when out of memory.  Floating point throughout: a near
 * touch counts as a touch. */
int geom_mesh_is_boundary(const double (*v)[3], int nv, const int (*tri)[3], int nt);

#endif

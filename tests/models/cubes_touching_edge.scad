// Two cubes that share only an edge, and a third through both (OpenSCAD's
// stl-import-nonmanifold.scad, from cubes-touching.stl).  The solid is not
// a manifold along the shared edge; its mesh must keep the two sides apart
// there: refine.c once split edges of both sides onto that edge at the same
// points, which a reader welding by position joins into edges of four
// triangles (make meshcheck reads it back at --facets=openscad).
union() {
    cube(1);
    translate([-1, -1, 0]) cube(1);
    translate([-0.5, -0.5, -0.5]) cube();
}

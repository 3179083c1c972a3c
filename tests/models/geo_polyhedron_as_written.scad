// args: --imgsize=480,360 --camera=2,0,0,55,0,25,120
// Polyhedra as users write them, drawn as openscad's preview draws them: a
// box with one face turned the wrong way (closed: a solid), a box without
// its top (open: its faces, the inside seen through the hole), a single
// triangle, a non-planar quadrilateral (libtess2's diagonal), hull() of
// coplanar points (a flat polygon).
P = [[0, 0, 0], [10, 0, 0], [10, 7, 0], [0, 7, 0],
     [0, 0, 5], [10, 0, 5], [10, 7, 5], [0, 7, 5]];
F = [[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]];
polyhedron(P, [F[0], F[1], [4, 5, 6, 7], F[3], F[4], F[5]]);
translate([0, 12, 0]) polyhedron(P, [F[0], F[1], F[3], F[4], F[5]]);
translate([-15, 0, 0]) polyhedron([[0, 0, 0], [0, 8, 0], [8, 0, 6]], [[0, 1, 2]]);
translate([-15, 12, 0]) polyhedron([[0, 0, 0], [4, -3, 4], [8, 0, 0], [4, 3, 4]], [[0, 1, 2, 3]]);
translate([15, 0, 0]) hull() polyhedron([[0, 0, 0], [6, 0, 0], [0, 6, 6], [3, 3, 3]], [[0, 1, 2, 3]]);

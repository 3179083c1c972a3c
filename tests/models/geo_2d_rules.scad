// args: --imgsize=480,360
// 2D rules of 2021.01, framed by openscad's default view: a path whose
// points lie on one line bounds nothing (it used to draw rounding noise and
// widen the frame); polygon(paths = []) takes the points in order; resize()
// of 2D children resizes 2D geometry, so a z scale below it no longer
// thickens their slab; rotate_extrude(45) names a file "45" and ignores its
// children; a polyhedron point no face uses is not framed; a 2D
// minkowski() with an empty operand is empty (a statement that makes no
// node is no operand).
polygon([[0, 0], [40, 40], [80, 80]]);
polygon([[0, 0], [6, 0], [6, 6], [0, 6]], paths = []);
translate([10, 0]) resize([10, 8], auto = [false, true]) scale([0.5, 100, 20]) square(2);
translate([-10, 0]) rotate_extrude(45) translate([3, 0]) square(2);
translate([0, -12, 0]) polyhedron([[0, 0, 0], [5, 0, 0], [0, 5, 0], [0, 0, 5], [-60, 0, 0]],
                                  [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);
translate([-30, 20]) minkowski() { square(5); circle(0); }
translate([-20, 10]) minkowski() { square(3); circle(1, $fn = 8); if (false) square(1); }

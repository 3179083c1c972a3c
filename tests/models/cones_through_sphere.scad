// OpenSCAD's example001: a sphere minus three cones through it (a round one,
// a square one and a triangular one).  At --facets=openscad two loops of one
// cell once took one point (the snapped point and its fallback both taken
// by other loops' vertices): a reader welding by position saw a vertex with
// two fans (make meshcheck exports the contour at those facets).
difference() {
    sphere(r = 25);
    rotate(90, [0, 0, 0]) cylinder(r1 = 6.25, r2 = 12.5, h = 62.5, center = true);
    rotate(90, [1, 0, 0]) cylinder(r1 = 6.25, r2 = 12.5, h = 62.5, center = true, $fn = 4);
    rotate(90, [0, 1, 0]) cylinder(r1 = 6.25, r2 = 12.5, h = 62.5, center = true, $fn = 3);
}

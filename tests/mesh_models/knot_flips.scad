// A faceted sphere and, far from it, a twisted prism on a grid of its own
// (crease.c scales it by the first grid's cell).  The prism's corner knots
// have rims that run along a crease out of the corner; a fan from the
// corner flips the needle such a rim edge would make, and once wrote an
// edge the mesh already had (non-manifold: no STL written).
translate([2.31, 3.77, -3.16]) sphere(2.16, $fn = 8);
translate([14, 0, 0]) linear_extrude(height = 5, twist = 20, slices = 2) square([2, 4], center = true);

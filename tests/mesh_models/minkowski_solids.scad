// minkowski() of solids that are not convex: a difference, a revolve and
// an extrusion of a concave polygon (each used to print error: and draw
// nothing), and an empty operand, which openscad passes over.
minkowski() {
    difference() { cube(10, center = true); cube([4, 4, 20], center = true); }
    sphere(1, $fn = 12);
}
translate([20, 0, 0]) minkowski() {
    rotate_extrude($fn = 24) translate([5, 0]) square([2, 3]);
    cube(1, center = true);
}
translate([0, 20, 0]) minkowski() {
    linear_extrude(3) polygon([[0, 0], [10, 0], [10, 10], [5, 3], [0, 10]]);
    linear_extrude(2) polygon([[0, 0], [3, 0], [3, 3], [1.5, 1], [0, 3]]);
    intersection() { cube(1); translate([5, 0, 0]) cube(1); }
}

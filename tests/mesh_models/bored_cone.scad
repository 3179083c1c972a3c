// A frustum with a bore and a cross hole: cones, concave cylinders, and
// the curves where they cut each other.
$fn = 96;
difference() {
    cylinder(r1 = 9, r2 = 4, h = 12);
    translate([0, 0, -1]) cylinder(r = 2, h = 14);
    translate([0, 0, 4]) rotate([0, 90, 0]) cylinder(r = 1.5, h = 20, center = true);
}

// hull() of extrusions (straight, twisted, partial revolve) with other
// solids: they were flattened to their outline at z = 0.
hull() {
    linear_extrude(10) square([20, 30]);
    translate([40, 0, 0]) cylinder(r = 5, h = 3, $fn = 20);
}
translate([0, 50, 0]) hull() {
    linear_extrude(height = 12, twist = 90, slices = 6) translate([4, 0]) square(3);
    rotate_extrude(angle = 90, $fn = 40) translate([5, 0]) square([3, 6]);
    translate([0, 0, 20]) sphere(2, $fn = 12);
}
translate([50, 50, 0]) linear_extrude(4) hull() {
    difference() { square(10); translate([5, 5]) square(10); }
    intersection() { translate([15, 0]) circle(4, $fn = 24); translate([15, -10]) square(20); }
}

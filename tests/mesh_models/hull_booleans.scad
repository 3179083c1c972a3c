// hull() of an intersection and of a difference: the vertices of the
// result, not of the uncut operands.
hull() intersection() {
    sphere(10, $fn = 30);
    translate([5, 0, 0]) cube(12, center = true);
}
translate([30, 0, 0]) hull() difference() {
    cube(20, center = true);
    translate([0, 0, 5]) cube([30, 30, 20], center = true);
    rotate([0, 0, 45]) cylinder(r = 4, h = 50, center = true, $fn = 12);
}

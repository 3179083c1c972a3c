// args: --imgsize=480,320
// hull() and minkowski() of booleans, extrusions and revolves, 2D and 3D,
// against openscad's own results: the hull of an intersection is of the
// cut solid, a difference's of what is left, an extrusion's of both caps.
hull() intersection() {
    sphere(10, $fn = 30);
    translate([5, 0, 0]) cube(12, center = true);
}
translate([25, 0, 0]) hull() difference() {
    cube(16, center = true);
    translate([0, 0, 5]) cube([30, 30, 20], center = true);
}
translate([50, 0, 0]) hull() rotate_extrude($fn = 32) translate([6, 0]) circle(2, $fn = 16);
translate([0, 30, 0]) hull() {
    linear_extrude(height = 8, twist = 60) translate([3, 0]) square(3);
    translate([10, 0, 0]) cylinder(r = 2, h = 2, $fn = 16);
}
translate([25, 30, 0]) hull() {
    difference() { square(12); translate([6, 6]) square(12); }
    translate([14, 0]) intersection() { circle(5, $fn = 24); translate([-10, 0]) square(20); }
}
translate([50, 30, 0]) minkowski() {
    difference() { cube(10, center = true); cube([4, 4, 20], center = true); }
    sphere(1, $fn = 12);
}
translate([0, 60, 0]) minkowski() {
    difference() { square(12, center = true); square(6, center = true); }
    circle(1, $fn = 12);
}
translate([25, 60, 0]) minkowski() {
    rotate_extrude($fn = 24) translate([5, 0]) square([2, 3]);
    cube(1, center = true);
}

// args: --imgsize=400,300 --camera=11,8,0,55,0,25,110
// minkowski(): a rounded box (cube ⊕ sphere), a union ⊕ a cylinder, 2D.
minkowski() {
    cube([12, 8, 4], center = true);
    sphere(2, $fn = 48);
}
translate([22, 0, 0]) minkowski() {
    union() {
        cube([10, 2, 2], center = true);
        cube([2, 10, 2], center = true);
    }
    cylinder(r = 1.5, h = 3, $fn = 48);
}
translate([0, 20, 0]) minkowski() {
    difference() { square(10, center = true); square(4, center = true); }
    circle(1, $fn = 48);
}

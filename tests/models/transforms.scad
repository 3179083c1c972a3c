// args: --imgsize=400,300
// translate, rotate (vector, scalar, axis-angle), scale, mirror, multmatrix.
$fn = 96;
translate([0, 0, 0]) rotate([30, 20, 10]) cube([6, 3, 2]);
translate([10, 0, 0]) rotate(45) cube([6, 3, 2]);
translate([20, 0, 0]) rotate(a = 60, v = [1, 1, 0]) cube([6, 3, 2]);
translate([0, 12, 0]) scale([2, 1, 0.5]) sphere(3);
translate([12, 12, 0]) mirror([1, 0, 0]) cylinder(h = 5, r1 = 3, r2 = 1);
translate([20, 12, 0]) multmatrix([[1, 0.5, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    cube(4);
translate([0, 24, 0]) scale(0.5) rotate([90, 0, 0]) cylinder(h = 6, r = 5, center = true);

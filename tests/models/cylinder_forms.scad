// args: --imgsize=400,300 --camera=10,10,0,65,0,20,110
// Every parameter form of cylinder().
$fn = 96;
cylinder(h = 10, r = 3);
translate([10, 0, 0]) cylinder(h = 10, r1 = 4, r2 = 2);
translate([20, 0, 0]) cylinder(h = 10, d1 = 6, d2 = 8);
translate([0, 12, 0]) cylinder(h = 10, d = 5, center = true);
translate([10, 12, 0]) cylinder(10, 4, 1);
translate([20, 12, 0]) cylinder(r = 3, h = 8, center = true);
translate([0, 24, 0]) cylinder(h = 6, r1 = 4, r2 = 0);
translate([10, 24, 0]) cylinder(h = 6, r1 = 0, r2 = 4);

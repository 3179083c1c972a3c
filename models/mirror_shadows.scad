// args: --imgsize=520,360 --camera=0,0,6,64,0,22,120
// rayscad-args: --samples 3 --light-samples 3
// A mirror scene with soft shadows.  The small sphere up left carries
// $rs_light: rayscad makes it an area light (its radius softens the
// shadows) and turns on its light model; the panel at the back carries
// $rs_reflect = 0.7 and shows the scene again.  OpenSCAD ignores both
// variables and shows the same objects.
$fn = 96;
color("white") translate([-40, -25, -1]) cube([80, 50, 1]);
color("DimGray") translate([-30, 14, 0]) cube([60, 2, 30], $rs_reflect = 0.7);
color("Tomato") translate([-12, -4, 7]) sphere(7);
color("RoyalBlue") translate([6, -10, 0]) cylinder(h = 16, r = 5);
color([0.3, 0.8, 0.4], 0.5) translate([16, 2, 0]) cube([10, 8, 10]);
color("Gold") translate([-2, 4, 0]) rotate(20) cube([8, 8, 8]);
color("white") translate([-26, -14, 42]) sphere(3, $rs_light = 0.9);
color("white") translate([20, -40, 90]) sphere(2, $rs_light = 0.35); // fill, out of view

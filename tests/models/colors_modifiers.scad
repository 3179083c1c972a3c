// args: --imgsize=320,240 --camera=6,0,2,60,0,20,60
// color() forms and the * and % modifiers; a disabled object must not show.
$fn = 96;
color("red") cube(4);
color([0, 0.5, 1]) translate([6, 0, 0]) sphere(2.5);
color("#80ff00") translate([12, 0, 0]) cylinder(h = 4, r = 2);
*translate([0, 8, 0]) cube(6);
color("blue", 0.5) translate([0, -8, 0]) cube([14, 3, 3]);

cube(0);
cube([0, 1, 1]);
sphere(0);
cylinder(h = 0, r = 1);
cylinder(h = 1, r = 0);
translate([0, 0, 3]) { square(0); circle(0); }

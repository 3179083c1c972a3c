// few primitives: a sphere, a box, a cylinder and a cone, smooth
sphere(10);
translate([25, 0, 0]) cube(16, center = true);
translate([0, 25, -8]) cylinder(r = 7, h = 16);
translate([-25, 0, -8]) cylinder(r1 = 8, r2 = 0, h = 16);

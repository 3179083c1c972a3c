translate([0 / 0, 0, 0]) cube();
cube(2);

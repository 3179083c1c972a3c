translate([1e20, 0, 0]) cube();
cube();

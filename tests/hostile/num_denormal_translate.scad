translate([1e-320, -1e-320, 5e-324]) cube(1e-320);

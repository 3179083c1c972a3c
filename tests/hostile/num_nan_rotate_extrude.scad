rotate_extrude(angle = 0 / 0) translate([2, 0]) square();
rotate_extrude(angle = 1 / 0) translate([2, 0]) square();
rotate_extrude(angle = 1e300) translate([2, 0]) circle();

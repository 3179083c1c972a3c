sphere(1, $fn = 1e9);
cylinder(h = 1, r = 1, $fn = 1e9);
translate([3, 0, 0]) circle(1, $fn = 1e9);

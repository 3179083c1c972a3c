rotate_extrude($fn = 1e9) translate([2, 0]) circle(1, $fn = 1e9);

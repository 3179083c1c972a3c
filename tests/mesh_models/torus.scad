// rotate_extrude of an offset circle: a torus (a revolve with a hole).
rotate_extrude($fn = 96) translate([8, 0]) circle(r = 3, $fn = 96);

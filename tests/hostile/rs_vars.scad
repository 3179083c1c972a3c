color("red", 0.5) sphere(3, $rs_reflect = 0 / 0, $rs_absorb = -1 / 0, $rs_ior = 1e308);
translate([6, 0, 0]) sphere(1, $rs_light = 1 / 0);
translate([-6, 0, 0]) cube(2, $rs_light = -1);

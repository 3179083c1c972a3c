translate([1e308, -1e308, 1e308]) cube(1e308);
sphere(1e308);

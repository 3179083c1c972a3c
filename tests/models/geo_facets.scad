// args: --imgsize=400,300 --camera=0,0,0,60,0,30,70
// Small $fn: --facets=auto builds OpenSCAD's own tessellation (sphere rings,
// prisms, pyramids) as convex polytopes.
sphere(6, $fn = 7);
translate([14, 0, 0]) cylinder(r = 5, h = 8, center = true, $fn = 5);
translate([-14, 0, -4]) cylinder(r1 = 5, r2 = 0, h = 9, $fn = 4);
translate([0, 14, 0]) sphere(4, $fn = 12);
translate([0, -14, -3]) cylinder(r1 = 2, r2 = 5, h = 6, $fn = 16);

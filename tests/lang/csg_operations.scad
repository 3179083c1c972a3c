// csg operations and colours in the dump
union() { cube(); sphere(); }
difference() { cube(3, center = true); sphere(2); }
intersection() { cube(); }
group() { }
render(convexity = 4) cube();
color("red") cube();
color([0, 0.5, 1]) cube();
color("#ff000080") cube();
color("blue", 0.5) cube();
color(alpha = 0.25) cube();
hull() { cube(); translate([2, 0, 0]) cube(); }
minkowski() { cube(); sphere(0.1); }

// Builtin modules bind their arguments as OpenSCAD 2021.01 does: positional
// arguments take the parameters in its order, extra ones warn, a named
// argument given twice warns, unknown names warn, union() and group() take
// none at all; .csg prints what the same reading gives the geometry.
offset(undef, 2) square(1);
minkowski(3) square(1);
render(4) cube(1);
resize([1,2,3], true, 7) cube(1);
projection(true, 5) cube(1);
rotate_extrude(angle=45, convexity=5) square(1);
linear_extrude(center=true, 5) square(1);
linear_extrude(5, center=true) square(1);
text("t", 5, "font", "dir");
cube(1, true, 5);
color("red", 0.5, 3) cube(1);
sphere(1, 2);
cylinder(1, 2, 3, true, 5);
square(1, true, 3);
circle(1, 2);
translate([1,0,0], 5) cube(1);
hull(1) cube(1);
union(foo=1) cube(1);
group($fn=6) sphere(1);
cube(size=2, 3);
cube(3, size=2);
cube(1, foo=1);
square([2,"a"]);
square([2,3,4]);
cube([2,"a",3]);
linear_extrude(1, scale=[2,"a"]) square(1);
cylinder(r=1, h=1, $fn=1/0);
sphere(d=2, r=5);

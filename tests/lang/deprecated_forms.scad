// Deprecated forms openscad 2021.01 still runs, each deprecation said once
// per place: child(), assign(), rotate_extrude(file=) (any value names the
// file), linear_extrude(file=), import(filename=, layername=) (issue 18)
module m() { child(0); child(); }
m() { cube(1); sphere(1); }
assign(a = 1, b = 2) { echo(a, b); cube(a); }
assign(x = 3) echo(x);
module two() { echo(n = $children); child(1); }
two() { cube(); sphere(); }
for (i = [0:2]) assign(k = i) echo(k);
linear_extrude(10) square(1);
rotate_extrude(45) translate([2,0]) square(1);
rotate_extrude("x.dxf") square(1);
linear_extrude("y.dxf", 5) square(1);
linear_extrude(file="z.dxf", height=3);
rotate_extrude(file="q.dxf");
import(filename = "nowhere.dxf", layername = "L");
import(filename = "nowhere2.dxf");

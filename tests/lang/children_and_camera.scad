// Primitives given children warn; the file's $vp* checked as openscad's camera
// does (issue 18)
cube([1,2], u) sphere();
polygon([[0,0],[1,0],[0,1]]) { echo("x"); cube(); }
sphere() echo("y");
cylinder() {}
square(1) circle();
text("a") cube();
surface("no.dat") cube();
import("no.stl") cube();
polyhedron([[0,0,0]], [[0]]) cube();
circle(1) {}
$vpr = "[1,2,3]";
$vpt = [1, 2, 3, 4];
$vpd = [1];

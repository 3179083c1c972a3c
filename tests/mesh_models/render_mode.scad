// What openscad's render exports: $preview is false there, and a 2D object
// beside 3D ones is left out ("Ignoring 2D child object for 3D operation"),
// also inside an operation.  The mesh is the cube and the cylinder alone.
if ($preview) sphere(20); else cube(10);
translate([20, 0, 0]) square(10);
translate([-20, 0, 0]) union() { cylinder(r = 4, h = 6, $fn = 24); circle(8); }

// What openscad's render exports: $preview is false there, and in a 3D
// operation a 2D child is an empty operand ("Ignoring 2D child object for
// 3D operation"): a union passes over it, an intersection with it is empty.
// A linear_extrude(1, center = true) is 3D though its prism is the preview
// slab of a 2D object.  The mesh is the cube, the cylinder and the slab.
if ($preview) sphere(20); else cube(10);
translate([20, 0, 0]) square(10);
translate([-20, 0, 0]) union() { cylinder(r = 4, h = 6, $fn = 24); circle(8); }
translate([0, -20, 0]) intersection() { cube(5); circle(2); }
translate([0, 20, 0]) linear_extrude(1, center = true) square(6);

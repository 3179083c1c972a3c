// hull() of a rotate_extrude: the hull of OpenSCAD's revolved polyhedron
// (was its bounding box: 4098 mm³ where openscad's is 2875).
hull() rotate_extrude($fn = 64) translate([10, 0]) circle(3, $fn = 32);

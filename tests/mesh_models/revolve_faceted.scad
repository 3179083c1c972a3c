// rotate_extrude at a small $fn is OpenSCAD's polyhedron (its fragments
// over the angle, rings from the -x axis for a whole turn), as its
// preview and its meshes are: a whole turn and a partial one with caps.
rotate_extrude($fn = 12) translate([5, 0]) circle(2, $fn = 8);
translate([0, 0, 6]) rotate_extrude(angle = 120, $fn = 12) translate([3, 0]) square([2, 4]);
translate([16, 0, 0]) rotate_extrude(angle = -200, $fn = 10) translate([-6, 0]) polygon([[0, 0], [-3, 0], [-1, 3]]);

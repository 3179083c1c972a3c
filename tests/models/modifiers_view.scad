// args: --imgsize=320,240
// '%' and '#' subtrees are framed by the default view, as in OpenSCAD.
$fn = 96;
cube(6);
translate([15, 0, 0]) %cube(10);
#translate([0, -12, 0]) sphere(3);

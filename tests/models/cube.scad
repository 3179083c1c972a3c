// args: --imgsize=300,240
// A plain cube in OpenSCAD's default view (rotation 55,0,25, viewall, autocenter).
cube([10, 6, 4]);

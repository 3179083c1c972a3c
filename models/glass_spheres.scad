// args: --imgsize=400,300 --camera=0,0,0,70,0,20,60
// Two overlapping see-through spheres.  Their union is one solid: a correct
// renderer shows no inner lens where they overlap (OpenSCAD's preview does).
$fn = 128;
color([0.2, 0.5, 1.0], 0.4) union() {
    sphere(8);
    translate([7, 0, 0]) sphere(8);
}

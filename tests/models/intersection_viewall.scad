// args: --imgsize=300,300
// The default view frames what OpenSCAD frames: the union of the positive
// leaves' boxes (here the whole cube and the whole sphere), not the
// intersection's exact bounds.
$fn = 96;
intersection() {
    cube([30, 12, 12], center = true);
    translate([6, 0, 0]) sphere(8);
}

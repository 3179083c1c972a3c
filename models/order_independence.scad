// args: --imgsize=480,360 --camera=0,0,2,62,0,28,100
// rayscad-args: --samples 3
// Order independence: three see-through solids that pass through one
// another.  A painter's-algorithm preview draws them in file order and gets
// some overlaps wrong; rayscad composites every surface along each ray in
// exact depth order, so any permutation of these lines renders the same
// image, bit for bit.  The union of the three has no inner faces: where two
// overlap you see only the outer skin.
$fn = 96;
color([1.0, 0.3, 0.2], 0.45) translate([-6, 0, 4]) sphere(10);
color([0.2, 0.5, 1.0], 0.45) rotate([0, 90, 0]) cylinder(h = 40, r = 5, center = true);
color([0.2, 0.8, 0.35], 0.45) translate([7, 3, 4]) cube([11, 11, 18], center = true);
color("Gold") translate([0, -2, -9]) cube([30, 20, 2], center = true);

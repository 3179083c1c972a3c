// The file's own $vpr/$vpt/$vpd/$vpf: with no --camera openscad renders
// from them (viewall and autocenter off), and so must rayscad.
$vpr = [70, 0, 300];
$vpt = [5, 2, 1];
$vpd = 80;
$vpf = 40;
cube([10, 5, 2]);
translate([0, 8, 0]) sphere(3, $fn = 64);
color("red") translate([-6, 0, 0]) cylinder(h = 6, r1 = 2, r2 = 0, $fn = 64);

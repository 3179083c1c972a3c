// args: --imgsize=320,240 --camera=30,-40,25,5,5,0
$fn = 96;
difference() {
    cube([10, 10, 10]);
    translate([5, 5, 5]) sphere(6);
}
translate([-8, 0, 0]) cylinder(h = 12, r1 = 3, r2 = 1);

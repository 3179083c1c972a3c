// args: --imgsize=360,240 --camera=8,0,4,75,0,15,60
$fn = 96;
union() {
    cube([16, 4, 4]);
    translate([8, 2, 2]) sphere(5);
    translate([0, 2, 2]) rotate([0, 90, 0]) cylinder(h = 20, r = 1.5);
}

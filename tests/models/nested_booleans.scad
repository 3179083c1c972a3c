// args: --imgsize=300,300 --camera=0,0,0,60,0,35,80 --projection=o
$fn = 96;
difference() {
    union() {
        cube([20, 20, 4], center = true);
        cylinder(h = 12, r = 6);
    }
    intersection() {
        translate([0, 0, 6]) sphere(7);
        cube([30, 4, 30], center = true);
    }
    for (x = [-7, 7], y = [-7, 7]) translate([x, y, 0]) cylinder(h = 10, r = 1.5, center = true);
}

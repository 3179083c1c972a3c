// args: --imgsize=400,300 --camera=12,0,0,0,0,0,90
// projection(): the shadow of a rotated box-minus-cylinder, and the z = 0 cut
// of a sphere minus a cube.
projection() rotate([30, 20, 0]) difference() {
    cube([16, 10, 6], center = true);
    cylinder(r = 3, h = 20, center = true, $fn = 96);
}
translate([26, 0]) projection(cut = true) translate([0, 0, 2]) difference() {
    sphere(8, $fn = 96);
    translate([0, 0, -4]) cube(8);
}

// args: --imgsize=300,300
// The classic: a cube minus a sphere minus three cylinders along the axes.
$fn = 96;
difference() {
    cube(20, center = true);
    sphere(11);
    cylinder(h = 30, r = 6.5, center = true);
    rotate([90, 0, 0]) cylinder(h = 30, r = 6.5, center = true);
    rotate([0, 90, 0]) cylinder(h = 30, r = 6.5, center = true);
}

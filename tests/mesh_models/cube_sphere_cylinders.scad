// The issue's example: a 20 mm cube minus a sphere of radius 11 minus three
// cylinders of radius 6.5 along the axes.  Exact volume 2404.778358.
$fn = 96;
difference() {
    cube(20, center = true);
    sphere(11);
    cylinder(r = 6.5, h = 30, center = true);
    rotate([90, 0, 0]) cylinder(r = 6.5, h = 30, center = true);
    rotate([0, 90, 0]) cylinder(r = 6.5, h = 30, center = true);
}

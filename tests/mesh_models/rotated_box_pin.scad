// A box turned off every axis, with a cylinder through it: sharp edges and
// corners that lie on no grid plane.
$fn = 96;
union() {
    rotate([20, 30, 40]) cube([14, 9, 6], center = true);
    cylinder(r = 2.5, h = 16, center = true);
}

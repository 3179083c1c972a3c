// A box whose corners hold notches smaller than three grid cells, and a
// twisted prism's acute corners beside them.
difference() {
    cube(10);
    translate([9.85, 9.85, 9.85]) cube(1);
    translate([-0.5, -0.5, 9.8]) cube([0.7, 0.62, 1]);
    translate([9.9, -0.5, -0.5]) rotate([0, 0, 30]) cube(0.4);
}
translate([14, 5, 0]) linear_extrude(height = 8, twist = 50, slices = 2) square([6, 4], center = true);

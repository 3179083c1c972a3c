// args: --imgsize=400,300
// openscad frames the leaves its normalised CSG products hold as positive
// terms: x - (y - z) becomes (x - y) + (x * z), so the wide cylinder below,
// subtracted twice, widens the frame; an intersection whose operands' boxes
// do not meet is pruned and frames nothing.
difference() {
    cylinder(h = 4, r = 12, center = true, $fn = 16);
    translate([4, 12, 0]) difference() {
        cube([5.5, 5.5, 10], center = true);
        translate([2.75, 2.75, 0]) cylinder(h = 11, r = 9, center = true, $fn = 8);
    }
}
intersection() {
    translate([-40, 0, 0]) cube(2);
    translate([-60, 0, 0]) cube(2);
}

// args: --imgsize=400,300 --camera=16,-7,0,0,0,0,110
// offset(): round (r), miter (delta), chamfer, negative, of a difference.
offset(r = 3, $fn = 64) square([14, 8]);
translate([24, 0]) offset(delta = 2) polygon([[0, 0], [10, 0], [5, 9]]);
translate([0, -22]) offset(delta = 2, chamfer = true) square(10);
translate([22, -22]) offset(r = -1.5, $fn = 64) difference() {
    square(14);
    translate([4, 4]) square(6);
}

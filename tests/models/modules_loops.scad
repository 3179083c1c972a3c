// args: --imgsize=400,300
// User modules with children(), for loops, if/else, let.
$fn = 96;
module post(h) {
    cylinder(h = h, r = 1);
    translate([0, 0, h]) children();
}
for (i = [0:4]) {
    let (x = i * 5)
    translate([x, 0, 0]) post(2 + i) {
        if (i % 2 == 0) sphere(1.5);
        else cube(2, center = true);
    }
}
for (a = [0, 120, 240], r = [8]) rotate(a) translate([r, 10, 0]) cube(1.5);

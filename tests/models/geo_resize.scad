// args: --imgsize=400,300 --camera=0,2,8,55,0,25,210
// resize(): the children's box scaled about the origin to the new size;
// auto axes take the largest newsize's scale; 2D children keep their slab.
resize([30, 10, 5]) sphere(4, $fn = 24);
translate([0, 20, 0]) resize([20, 0, 0], auto = [false, true, false])
    difference() {
        cylinder(r = 3, h = 8, $fn = 6);
        translate([0, 0, 4]) cube(4, center = true);
    }
translate([-30, -15, 0]) resize([0, 0, 25], auto = true) rotate([0, 0, 30]) cube([6, 3, 5]);
translate([25, -15, 0]) resize([12, 6]) translate([3, 3]) circle(5, $fn = 7);
translate([25, 15, 0]) linear_extrude(4) resize([18, 0], auto = 1) polygon([[0, 0], [6, 1], [2, 5]]);

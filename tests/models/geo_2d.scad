// args: --imgsize=400,300 --camera=0,0,0,50,0,20,80
// A top level of 2D objects: OpenSCAD's preview draws them as slabs 2 mm thick.
difference() {
    square([20, 12]);
    translate([6, 6]) circle(4, $fn = 96);
}
translate([-14, 0]) polygon(points = [[0, 0], [10, 0], [10, 10], [0, 10], [3, 3], [7, 3], [7, 7], [3, 7]],
                            paths = [[0, 1, 2, 3], [4, 5, 6, 7]]);
translate([8, -14]) rotate(30) square(8, center = true);
translate([-8, -12]) circle(5, $fn = 6);

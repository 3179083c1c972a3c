// args: --imgsize=480,360 --camera=0,2,6,55,0,25,190
// linear_extrude with twist, scale and slices: OpenSCAD's own slices as a
// closed polyhedron (default slices from $fn/$fa/$fs, shorter diagonals).
translate([-30, 20, 0]) linear_extrude(height = 20, twist = 90) square([20, 10], center = true);
translate([0, 20, 0]) linear_extrude(height = 20, scale = 0.2) square([20, 10], center = true);
translate([30, 20, 0])
    linear_extrude(height = 30, twist = -360, scale = 0, center = true, slices = 60)
        square([16, 8], center = true);
// a hole, off-centre discs (OpenSCAD's fragments), non-uniform scale
translate([-30, -15, 0]) linear_extrude(height = 24, twist = 120, scale = [1.5, 0.6])
    difference() {
        square(16, center = true);
        circle(4);
    }
translate([0, -15, 0]) linear_extrude(height = 24, twist = 270, $fn = 24)
    translate([5, 0]) circle(3);
translate([30, -15, 0]) linear_extrude(24, twist = 60, slices = 3, scale = [0.5, 1.5])
    polygon([[0, 0], [10, 0], [10, 3], [3, 3], [3, 10], [0, 10]]);

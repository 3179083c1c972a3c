// Twisted extrusions whose quads have two equal diagonals (an edge in line
// with the origin): 2021.01 breaks the tie by its walk (outer paths
// counter-clockwise, holes clockwise) and the twist's direction.  The
// square at x = 10 measured 10 % under openscad's when we walked the other
// way.
linear_extrude(height = 10, twist = 40, slices = 1) translate([10, 0]) square(4);
translate([0, 30, 0]) linear_extrude(height = 10, twist = -40, slices = 1) translate([10, 0]) square(4);
translate([-30, 0, 0]) linear_extrude(height = 4.7, twist = 90, slices = 1, $fn = 4) translate([-3, 0]) circle(3);
translate([-30, 30, 0]) linear_extrude(height = 6, twist = 60, slices = 2)
    difference() { square([12, 8], center = true); square([4, 4], center = true); }

// hull() as libraries use it: a rounded box (the hull of eight spheres,
// 2,300 faces) minus the hull of a revolved circle (a ring's outer half,
// 2,000 faces).  Each line meets two polytopes of thousands of planes.
difference() {
    hull() for (x = [-10, 10], y = [-6, 6], z = [-4, 4]) translate([x, y, z]) sphere(3, $fn = 48);
    translate([0, 0, 7]) hull() rotate_extrude($fn = 64) translate([5, 0]) circle(2, $fn = 32);
}

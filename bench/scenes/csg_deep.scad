// CSG-heavy: a plate cut by 48 holes inside a chain of 12 nested differences,
// each level subtracting a sphere from the result of the level below.
module level(i) {
    if (i == 0) {
        difference() {
            cube([60, 60, 10], center = true);
            for (x = [-25 : 10 : 25], y = [-25 : 10 : 25])
                if ((x + y) % 20 != 0) translate([x, y, -10]) cylinder(r = 3, h = 20);
        }
    } else {
        difference() {
            level(i - 1);
            rotate([0, 0, i * 30]) translate([22, 0, 5]) sphere(4 + i * 0.3);
        }
    }
}
level(12);

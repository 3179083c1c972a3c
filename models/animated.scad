// An animation: --animate N renders N frames with $t = i/N (rayscad and
// openscad alike).  A disc with a bore turns once, three balls orbit it
// and bob, and the camera circles the scene.
// args: --imgsize=320,240
$vpr = [62, 0, 30 + 360 * $t];
$vpt = [0, 0, 4];
$vpd = 120;

color("SteelBlue") rotate([0, 0, 120 * $t]) difference() {
    cylinder(r = 14, h = 4, $fn = 64);
    translate([0, 0, -1]) cylinder(r = 4, h = 6, $fn = 32);
    for (a = [0 : 60 : 359]) rotate([0, 0, a]) translate([9, 0, -1]) cylinder(r = 2, h = 6, $fn = 24);
}
for (k = [0 : 2]) {
    a = 360 * $t + 120 * k;
    color(["Tomato", "Gold", "MediumSeaGreen"][k])
        translate([22 * cos(a), 22 * sin(a), 6 + 4 * sin(720 * $t + 120 * k)]) sphere(r = 4, $fn = 48);
}
color("Gray") translate([0, 0, -1]) cube([60, 60, 2], center = true);

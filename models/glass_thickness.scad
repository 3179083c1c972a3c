// args: --imgsize=520,280 --camera=0,2,9,66,0,0,150
// rayscad-args: --shadows --samples 3
// Thick versus thin glass.  Front row: colour alpha, as OpenSCAD shows it —
// every pane looks the same however thick.  Back row: the same colour with
// $rs_absorb (an absorption coefficient per mm, ignored by OpenSCAD), so
// each pane darkens by Beer-Lambert over the length of glass the ray
// crosses: 1, 3, 6 and 12 mm, and the sphere clears towards its rim.
$fn = 96;
glass = [0.25, 0.55, 0.95];
color("white") translate([-46, -16, -1]) cube([92, 40, 1]);
for (i = [0:3]) {
    t = [1, 3, 6, 12][i];
    color(glass, 0.35) translate([-40 + i * 18, -12, 0]) cube([12, t, 14]);
    color(glass, 0.35) translate([-40 + i * 18, 4, 0]) cube([12, t, 14], $rs_absorb = 0.12);
}
color(glass, 0.35) translate([36, 4, 8]) sphere(8, $rs_absorb = 0.12);
color("Tomato") translate([-44, 18, 0]) cube([88, 2, 22]);

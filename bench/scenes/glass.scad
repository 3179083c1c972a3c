// transparency-heavy: 64 overlapping see-through spheres in 4 colours,
// around an opaque core (every pixel composites many boundaries).
color("gray") cube(12, center = true);
for (i = [0 : 63]) {
    a = i * 137.508;
    r = 6 + 14 * sqrt(i / 63);
    color([(i % 4) / 3, 0.5, 1 - (i % 4) / 3], 0.25)
        translate([r * cos(a), r * sin(a), (i % 7) * 3 - 9]) sphere(7);
}

// args: --imgsize=480,360 --camera=0,-250,50,0,50,50
// rayscad-args: --path-trace=128
// A Cornell-box-like room for the path-traced quality mode: white floor,
// ceiling and back wall, a red wall on the left and a green one on the
// right, lit only by the panel in the ceiling ($rs_light).  Path tracing
// carries the light on from wall to wall, so the white surfaces take on
// red and green near the coloured walls and the shadows are never black.
// The sphere is glass ($rs_ior: refraction with Fresnel reflection; its
// caustic lies on the floor), the tall block a mirror ($rs_reflect).
// OpenSCAD ignores the $rs_ variables and shows the same objects.
$fn = 96;
w = 130;  // inside width (x)
d = 110;  // depth (y)
h = 100;  // height (z)
t = 4;    // wall thickness

color([0.85, 0.85, 0.82]) {
    translate([-w / 2, 0, -t]) cube([w, d + t, t]);       // floor
    difference() {                                        // ceiling, with an
        translate([-w / 2, 0, h]) cube([w, d + t, t]);    // opening for the light
        translate([-18, 40, h - 1]) cube([36, 30, t]);
    }
    translate([-w / 2, d, 0]) cube([w, t, h]);            // back wall
}
color([0.75, 0.12, 0.1]) translate([-w / 2 - t, 0, -t]) cube([t, d + t, h + 2 * t]);
color([0.15, 0.6, 0.18]) translate([w / 2, 0, -t]) cube([t, d + t, h + 2 * t]);

// the light: a panel above the opening, wider than it, so that only its
// underside shows (its edges, buried in the ceiling, would light the
// ceiling next to them at grazing distances: noise for no picture)
color("white") translate([-20, 38, h + 0.5]) cube([40, 34, 2], $rs_light = 3);

// a mirror block, turned toward the room
color([0.8, 0.82, 0.85]) translate([-30, 66, 0]) rotate(35)
    translate([-14, -14, 0]) cube([28, 28, 62], $rs_reflect = 0.85);

// a glass sphere
color([1, 1, 1], 0.04) translate([24, 40, 20]) sphere(20, $rs_ior = 1.5);

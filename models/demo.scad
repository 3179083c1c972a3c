// args: --imgsize=800,600 --camera=5,-4,4,58,0,18,190
// rayscad demo: CSG with exact surfaces and see-through colours.
$fn = 128;

// A machined block: a cube minus a sphere minus three bores.
module block(s) {
    difference() {
        cube(s, center = true);
        sphere(s * 0.56);
        for (r = [[0, 0, 0], [90, 0, 0], [0, 90, 0]])
            rotate(r) cylinder(h = 2 * s, r = s * 0.33, center = true);
    }
}

// A glass shell around an opaque core.
module shell(r) {
    color("Tomato") sphere(r * 0.45);
    color([0.55, 0.8, 1.0], 0.3) difference() {
        sphere(r);
        sphere(r * 0.9);
        translate([0, -r, r * 0.3]) cube(2 * r, center = true);
    }
}

color("Gold") translate([-22, 0, 10]) block(20);
translate([8, 6, 11]) shell(11);
// Two see-through spheres: their union has no inner face.
color("MediumSeaGreen", 0.45) translate([30, -12, 7]) union() {
    sphere(7);
    translate([6, 4, 2]) sphere(6);
}
// A base plate with a row of countersunk holes.
color("LightSlateGray") difference() {
    translate([-40, -30, -2]) cube([90, 55, 2]);
    for (x = [-30:12:42]) translate([x, 18, -3]) {
        cylinder(h = 4, r = 2.5);
        translate([0, 0, 3.2]) cylinder(h = 1, r1 = 2.5, r2 = 4.5);
    }
}

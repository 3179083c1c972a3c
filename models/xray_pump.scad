// args: --imgsize=480,360 --camera=0,0,14,62,0,32,140
// rayscad-args: --xray=0.3 --samples 3
// X-ray view of a mechanical part.  Plain rendering shows a closed pump
// housing; with --xray every surface is at most 30 % opaque and the bores,
// the shaft, its bearing seats and the impeller inside show through, each
// cut face in the colour OpenSCAD gives it.
$fn = 96;
module housing() {
    difference() {
        union() {
            cylinder(h = 30, r = 16);
            translate([-22, -6, 0]) cube([44, 12, 4]);          // foot
            translate([0, 0, 14]) rotate([0, 90, 0]) cylinder(h = 26, r = 6); // outlet
        }
        translate([0, 0, 4]) cylinder(h = 22, r = 12);           // impeller chamber
        translate([0, 0, -1]) cylinder(h = 40, r = 4);           // shaft bore
        translate([0, 0, 14]) rotate([0, 90, 0]) cylinder(h = 30, r = 4); // outlet bore
        for (x = [-18, 18]) translate([x, 0, -1]) cylinder(h = 6, r = 2); // bolt holes
        translate([0, 0, 26]) cylinder(h = 5, r = 7);            // bearing seat
    }
}
color("LightSteelBlue") housing();
color("Crimson") translate([0, 0, -6]) cylinder(h = 42, r = 3.5); // shaft
color("Orange") for (a = [0:60:300]) rotate(a) translate([3, -1, 8]) cube([8, 2, 12]); // impeller

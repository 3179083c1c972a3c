// args: --imgsize=400,300 --camera=0,0,0,60,0,20,110
// rotate_extrude: exact solids of revolution of polygon profiles, full and
// partial (the sweep starts at +x), and a profile on the negative side.
rotate_extrude() polygon([[5, 0], [10, 0], [10, 2], [7, 6], [5, 6]]);
translate([26, 0, 0]) rotate_extrude(angle = 270) translate([4, 0]) square([3, 8]);
translate([-26, 0, 0]) rotate_extrude(angle = 120) translate([-9, 0]) square([4, 5]);
// A profile whose circle reaches x < 0 but is cut back to x >= 0 by an
// intersection: only the result's side of the axis counts.
translate([0, 26, 0]) rotate_extrude($fn = 96) intersection() { square(6); circle(6); }

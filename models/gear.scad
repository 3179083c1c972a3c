// args: --imgsize=480,360 --camera=0,0,0,50,0,20,110
// A spur-gear-like wheel: modules, loops and deep differences.
$fn = 128;
module tooth(r, w, h) translate([r, -w / 2, 0]) cube([4, w, h]);
module wheel(r, teeth, h) {
    difference() {
        union() {
            cylinder(h = h, r = r);
            for (i = [0:teeth - 1]) rotate(i * 360 / teeth) tooth(r - 1, 3, h);
        }
        translate([0, 0, -1]) cylinder(h = h + 2, r = 4);
        for (i = [0:5]) rotate(i * 60 + 30) translate([r * 0.6, 0, -1]) cylinder(h = h + 2, r = 3.5);
        translate([0, 0, h - 1.5]) difference() {
            cylinder(h = 2, r = r - 2);
            cylinder(h = 2, r = r * 0.35);
        }
    }
}
color("SteelBlue") wheel(22, 24, 6);

// args: --imgsize=400,300 --camera=0,0,0,55,0,25,80
// hull() of OpenSCAD's tessellations, 3D and 2D.
hull() {
    sphere(4, $fn = 24);
    translate([14, 0, 0]) cube(4, center = true);
    translate([0, 10, 4]) cylinder(r = 2, h = 3, $fn = 12);
}
translate([-12, -8, 0]) hull() {
    circle(3, $fn = 20);
    translate([0, -10]) square(2);
}

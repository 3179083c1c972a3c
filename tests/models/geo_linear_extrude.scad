// args: --imgsize=400,300 --camera=0,0,0,60,0,25,90
// linear_extrude of 2D booleans and transforms: exact prisms.
linear_extrude(height = 10, center = true)
difference() {
    square([20, 14], center = true);
    circle(5, $fn = 96);
    translate([8, 5]) rotate(45) square(4, center = true);
}
translate([-22, 0, 0]) linear_extrude(6)
    polygon([[0, 0], [8, 0], [8, 2], [2, 2], [2, 8], [0, 8]]);
translate([20, 0, 0]) scale([1, 2, 1]) linear_extrude(8) circle(3, $fn = 96);

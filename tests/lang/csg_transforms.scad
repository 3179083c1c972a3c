// transforms become multmatrix in the csg dump
translate([1, 2, 3]) cube();
rotate([90, 0, 0]) cube();
rotate(45) cube();
rotate(a = 30, v = [1, 1, 0]) cube();
rotate(90, [0, 0, 0]) cube();
scale(2) cube();
scale([1, 2, 3]) cube();
mirror([1, 0, 0]) cube();
mirror([1, 1, 0]) cube();
multmatrix([[1, 0, 0, 5], [0, 1, 0, 6], [0, 0, 1, 7], [0, 0, 0, 1]]) cube();
translate([1, 0, 0]) rotate([0, 0, 90]) scale([2, 1, 1]) cube();

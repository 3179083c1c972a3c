// primitive argument forms and their warnings
cube(5, foo = 1);
cube([1, 2, 3], center = true);
sphere(r = 1, d = 2);
sphere(d = 4);
cylinder(h = 1, r = 1, d = 3);
cylinder(h = 1, r1 = 1, r2 = 2, d1 = 4);
cylinder(h = 2, d1 = 2, d2 = 4, center = true);
cylinder(2, 1, 0);
cube(-1);
sphere(0);
cylinder(h = -1);
translate([1, 2]) cube(1);
rotate(a = [10, 20]) cube(1);
rotate(45, [1, 1, 0]) cube(1);
scale(2) mirror([1, 0, 0]) multmatrix([[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 3]]) cube(1);
union() { cube(1); sphere(1); }
difference() { echo("first"); cube(5); sphere(1); }
intersection_for (i = [0 : 2]) rotate(i * 30) cube(1);
render(convexity = 2) cube(1);
group() cube(1);

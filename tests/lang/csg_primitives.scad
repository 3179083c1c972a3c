// primitive arguments as the csg dump resolves them
cube(2);
cube([1, 2, 3], center = true);
cube(size = [1, 2]);
sphere(r = 2, $fn = 12);
sphere(d = 4);
cylinder(h = 3, r1 = 1, r2 = 2, center = true);
cylinder(d = 2, h = 5, $fa = 6, $fs = 0.5);
cylinder(5, 2, 3);
square(3);
square([2, 4], center = true);
circle(d = 6);
polygon([[0, 0], [1, 0], [0, 1]]);
polygon(points = [[0, 0], [4, 0], [0, 4], [1, 1], [2, 1], [1, 2]], paths = [[0, 1, 2], [3, 4, 5]], convexity = 2);
polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);

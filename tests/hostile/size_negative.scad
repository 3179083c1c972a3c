cube(-1);
cube([-1, 2, 3]);
sphere(-2);
cylinder(h = -1, r = -1);
cylinder(h = 2, r1 = -1, r2 = 2);
square([-1, 1]);
circle(-1);

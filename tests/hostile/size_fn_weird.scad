$fn = 0 / 0;
sphere(1);
cylinder(h = 1, r = 1, $fn = 1 / 0);
circle(1, $fn = -1);
sphere(2, $fn = "abc");
sphere(3, $fa = 0, $fs = 0);
sphere(4, $fa = -1, $fs = 1e-300);
sphere(5, $fn = 3);
sphere(6, $fn = 1);

sphere(-1 / 0);
sphere(r = 1 / 0);
cylinder(h = 1 / 0, r = 1);

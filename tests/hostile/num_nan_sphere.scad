sphere(0 / 0);
cylinder(h = 0 / 0, r1 = 1 / 0, r2 = -1);
cylinder(h = 2, d = 0 / 0);

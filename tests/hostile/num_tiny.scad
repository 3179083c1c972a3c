cube(1e-300);
sphere(5e-324);
cylinder(h = 1e-310, r = 1e-310);

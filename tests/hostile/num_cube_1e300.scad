cube(1e300);

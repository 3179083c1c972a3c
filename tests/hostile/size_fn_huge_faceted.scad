hull() sphere(1, $fn = 1e9);

minkowski() { sphere(1, $fn = 1e9); sphere(1, $fn = 1e9); }

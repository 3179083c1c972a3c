linear_extrude(height = 1, twist = 90) circle(1, $fn = 1e9);

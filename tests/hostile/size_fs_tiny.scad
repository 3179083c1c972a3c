linear_extrude(height = 1, twist = 30) circle(10, $fa = 1e-300, $fs = 1e-300);

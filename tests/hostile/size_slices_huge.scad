linear_extrude(height = 1, twist = 10, slices = 1e9) square();
linear_extrude(height = 1, twist = 10, slices = -5) square();

linear_extrude(height = 0 / 0) square();
linear_extrude(height = 1 / 0) square();
linear_extrude(height = 1, twist = 1 / 0) square();
linear_extrude(height = 1, scale = 0 / 0) square();
linear_extrude(height = 1, center = true, slices = 0 / 0, twist = 10) square();

color([0 / 0, 1 / 0, -1]) cube();
color([1, 0, 0], 0 / 0) sphere();
color("#zzzzzz") cube();
color([1e308, 1e308]) cube();

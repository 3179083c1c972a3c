resize([0 / 0, 1 / 0, 0]) cube();
resize([1e308, 1e308, 1e308]) sphere();
resize([-1, -1, -1]) cube();
resize([0, 0, 0], auto = true) cube();

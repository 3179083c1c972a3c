scale(0) cube();
scale([1, 0, 1]) sphere();
scale([1e-300, 1, 1]) cube();

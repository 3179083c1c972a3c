scale(1 / 0) cube();
scale([1 / 0, -1 / 0, 0 / 0]) sphere();

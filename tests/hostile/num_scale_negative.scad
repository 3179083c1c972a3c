scale(-1) cube();
scale([-1, 2, -3]) sphere(2);

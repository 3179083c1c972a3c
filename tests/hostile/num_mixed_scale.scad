scale([1e300, 1e-300, 1]) cube();
scale([1e154, 1e154, 1e154]) sphere();

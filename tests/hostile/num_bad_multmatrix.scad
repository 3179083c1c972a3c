multmatrix([1, 2, 3]) cube();
multmatrix([[1, 2], [3]]) cube();
multmatrix("x") cube();
multmatrix([[[1]]]) cube();
multmatrix() cube();

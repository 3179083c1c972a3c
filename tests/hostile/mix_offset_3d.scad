offset(1) cube();
offset(delta = 1) sphere();

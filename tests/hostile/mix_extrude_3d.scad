linear_extrude(1) cube();
rotate_extrude() sphere();
linear_extrude(1) linear_extrude(1) square();

rotate([0 / 0, 1 / 0, 0]) cube();
rotate(a = 0 / 0, v = [0, 0, 1]) cube();
rotate(a = 45, v = [0, 0, 0]) cube();
rotate(a = 45, v = [0 / 0, 1, 0]) cube();

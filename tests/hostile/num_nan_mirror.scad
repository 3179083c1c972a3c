mirror([0 / 0, 0, 0]) cube();
mirror([0, 0, 0]) cube();
mirror([1 / 0, 1, 0]) cube();

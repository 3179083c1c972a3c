module tree(n) { cube(1); translate([0, 0, 1]) tree(n + 1); }
tree(0);

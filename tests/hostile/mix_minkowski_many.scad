minkowski() { for (i = [0:99]) translate([i, 0, 0]) cube(); for (i = [0:99]) translate([0, i, 0]) cube(); }

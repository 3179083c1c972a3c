hull() for (i = [0:99999]) translate([cos(i) * 10, sin(i) * 10, i % 10]) cube(0.1);

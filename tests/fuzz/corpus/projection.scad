projection(cut=true) translate([0,0,-1]) cube(3);
projection() sphere(2, $fn=8);

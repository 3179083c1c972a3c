minkowski() { square(4); circle(1, $fn=6); }
linear_extrude(2, twist=30, slices=3) minkowski() { square(2, center=true); square(1); }

// 2D operations and extrusions in the dump
linear_extrude(5) square();
linear_extrude(height = 3, center = true, twist = 90, slices = 10, scale = [1, 0.5]) circle(2);
linear_extrude(height = 2, scale = 2, $fn = 16) circle(1);
rotate_extrude() translate([2, 0]) circle(1);
rotate_extrude(angle = 90, convexity = 4) square();
offset(r = 1) square();
offset(delta = 0.5, chamfer = true) square();
offset(-0.5) square(2);
projection(cut = true) cube(3, center = true);
resize([4, 5, 0], auto = [false, false, true]) cube();
text("Hello", size = 5, halign = "center");

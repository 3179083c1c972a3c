color("") cube();
color("nosuchcolor") sphere();
color("#") cube();
color("#12345") cube();
color("#1234567890") cube();
color([]) cube();
color(undef, 2) cube();
color(1) cube();

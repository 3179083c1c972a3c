// every color() form; bad ones warn
color("red") cube(1);
color("DarkSlateGray") cube(1);
color("#f00") cube(1);
color("#ff000080") cube(1);
color("#12345") cube(1);
color("nonsense") cube(1);
color([1, 0, 0]) cube(1);
color([1, 0, 0, 0.5]) cube(1);
color([2, 0, -1]) cube(1);
color("blue", 0.5) cube(1);
color(c = "green", alpha = 0.25) cube(1);
color(alpha = 0.5) cube(1);
color("transparent") cube(1);
color("red") color("blue") echo("inner");

text("abc", size = 0 / 0);
text("", size = 10);
text("x", size = 1e300);
text("x", size = -5, spacing = 1 / 0);
text(42);
linear_extrude(1) text("hostile", font = "No Such Font:style=Nope");
text(str([for (i = [0:999]) "W"]));

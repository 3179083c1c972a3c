polygon([[0, 0], [10, 10], [10, 0], [0, 10]]);
translate([20, 0]) polygon([for (i = [0:4]) 10 * [cos(i * 144), sin(i * 144)]]);

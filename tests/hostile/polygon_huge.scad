n = 200000;
polygon([for (i = [0:n - 1]) [10 * cos(i * 360 / n), 10 * sin(i * 360 / n)]]);

echo(undef, true, [], [[]], "", [0:0], function(x) x, 1e308, -0, 0 / 0, 1 / 0, -1 / 0);
echo(a = 1, 2, b = [3], "c" = 4);

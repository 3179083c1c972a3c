x = [each [0:1e9]];
echo(len(x));
y = [for (i = [0:1e6]) each [i, i]];
echo(len(y));

x = [for (i = [0:999998]) i];
echo(len(concat(x, x, x, x, x, x, x, x)));

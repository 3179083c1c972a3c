x = [for (i = [0:999999]) i];
echo(len(concat(x, x, x, x, x, x, x, x)));

x = [for (i = [0:1e6]) for (j = [0:1e6]) i];
echo(len(x));

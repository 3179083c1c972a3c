x = [for (i = [0:999]) for (j = [0:999]) for (k = [0:999]) if (i < 0) k];
echo(len(x));

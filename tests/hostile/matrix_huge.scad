m = [for (i = [0:499]) [for (j = [0:499]) i + j]];
echo(len(m * m));

x = (y = 3);
echo(x);

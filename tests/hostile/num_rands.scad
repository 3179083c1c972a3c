echo(len(rands(0, 1, 1e9)));
echo(rands(0 / 0, 1 / 0, 3, 0 / 0));
echo(rands(1, 0, -5));

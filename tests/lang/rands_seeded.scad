// rands: only properties that do not depend on the generator
r = rands(0, 1, 10, 42);
echo(len(r), min(r) >= 0, max(r) <= 1);
echo(rands(5, 5, 3, 1));
echo(len(rands(0, 10, 0)));

function f(x) = f(x + 1);
echo(f(0));

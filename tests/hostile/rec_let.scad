function f(x) = let(y = f(x)) y;
echo(f(1));

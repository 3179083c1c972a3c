function f(n) = [for (i = [0:1]) f(n + 1)];
echo(f(0));

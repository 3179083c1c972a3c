x = let(a = 1, a = 2, a = 3) a;
echo(x);
function f(n) = let(m = [for (i = [0:n]) i]) len(m);
echo(f(1e6));

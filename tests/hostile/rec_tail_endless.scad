function f(x) = f(x + 1);
function g(x) = x < 0 ? 0 : g(x + 1);
echo(g(0));

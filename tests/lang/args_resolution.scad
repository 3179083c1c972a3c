// Argument resolution: duplicates, extra positional arguments, unknown names.
module m2(x) { echo(x); }
m2(x = (echo("a") 1), x = (echo("b") 2));
cube(size = (echo("a") 1), size = (echo("b") 2));
echo(a = 1, a = 2);
function f4(x) = x;
echo(f4(1, x = 2));
echo(f4(x = 2, 1));
m2((echo("a") 1), (echo("b") 2));
module m3(x) { echo(x); }
m3(q = (echo("a") 1), (echo("b") 2));
function f5(x) = x;
echo(f5(q = (echo("a") 1)));
echo(f5((echo("a") 1), x = (echo("b") 2)));
echo(f5(x = (echo("a") 1), (echo("b") 2)));
cube(q = 1);
m3($fn = (echo("a") 1), (echo("b") 2), $fn = (echo("c") 3));
module m4(x) { echo(q); }
m4(q = 5);
function f6(x) = q;
echo(f6(q = 6));
function g6(x) = x;
echo(g6(1, 2, (echo("c") 3)));
echo(g6((echo("a") 1), x = (echo("b") 2), x = (echo("c") 3)));

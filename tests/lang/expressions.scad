// echo() and assert() as expressions, let, nested functions as values
x = echo("side effect") 5;
echo(x = x);
y = assert(x == 5) x + 1;
echo(y = y);
z = let(a = 1, b = 2) echo(a = a) a + b;
echo(z = z);
f = function(x, y = 2) x > 0 ? [x, -y, "s", !x, x[0], x.y, [1 : 2 : 3], let(a = 1) a] : undef;
echo(f);
g = function(v) [for (i = v) if (i) i else -i, each v, for (i = 0; i < 2; i = i + 1) i];
echo(g);
h = function() assert(true) echo("x") 1 + 2 * 3 - (4 - 5) ^ 2 % 7 / 8 == 9 != 10 && 11 || 12 < 13;
echo(h);
k = function(z) function(q) z + q;
echo(k, k(1)(2));

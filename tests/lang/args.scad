// argument binding: positional, named, defaults, extra and unknown names
module m(a, b = 2) echo(a = a, b = b);
m(1);
m(1, 3);
m(b = 4, a = 5);
m(c = 1);
m(1, 2, 3);
module d(a = 1, b = a + 1) echo(b = b);
d(a = 5);
function f(a, b = 10) = a + b;
echo(f(1), f(1, 2), f(b = 1, a = 2));
module specials() echo(fn = $fn, fa = $fa, fs = $fs);
specials();
specials($fn = 12);
$fn = 6;
specials();

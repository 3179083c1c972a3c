// the last assignment of a name wins, at the first one's position
a = 1;
echo(a = a, b = b);
b = a * 10;
a = 2;
x = 1;
module show() echo(x = x, y = $y);
module outer() { x = 2; $y = 5; show(); }
outer();
$y = 7;
show();
module shadow(x) { echo(inner = x); x = 3; }
shadow(9);
if (true) { c = 1; echo(c = c); c = 2; }
echo(c_outside = c);
function f() = x;
module g() { x = 100; echo(f = f()); }
g();

// $children is lexical: inside a child block it is the caller's count;
// other $-variables are dynamic (issue 18)
module m() { $fn = 10; $foo = 3; echo(mc = $children); children(); }
module outer() { $foo = 5; m() { echo(inner = $children, fn = $fn, foo = $foo); } }
outer() { cube(); sphere(); }
m() echo(top = $children, fn = $fn, foo = $foo);
module n() { children(); }
module o() { $bar = 1; n() n() echo(b = $bar, c = $children); }
o() { cube(); cube(); cube(); }
function f() = $children;
module mm() echo(f = f());
mm() cube();
// a $fn given to a function call goes on through its recursive calls
function g(n) = n == 0 ? $fn : g(n - 1);
function h(n) = n == 0 ? [$fn, $fa] : let($fa = 7) h(n - 1);
echo(g(3, $fn = 7), g(0), h(2, $fn = 9));
function k(n) = n == 0 ? $fn : 1 + k(n - 1);
echo(k(3, $fn = 5));
echo($vpf, $vpd, $vpr, $vpt);

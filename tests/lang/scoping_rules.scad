// lexical scoping of variables, functions and modules
a = 1;
module m() { echo(a = a); a = 2; echo(a2 = a); }
m();
echo(a = a);
function f() = a;
module n() { a = 5; echo(f()); }
n();
module outer() {
    function g() = 10;
    module inner() echo(g());
    inner();
}
outer();
if (true) { b = 3; echo(b = b); }
echo(b = b);
x = 1;
x = 2;
echo(x = x);
module shadow(a) { echo(a = a); }
shadow(9);

// An assertion fails inside a function inside echo() inside a module: the
// .echo holds what came before, the ERROR line and the TRACE of calls.
function f(x) = assert(x > 0, "neg") x;
module m(a) { echo(f(a)); }
echo(1);
m(-1);
echo(2);

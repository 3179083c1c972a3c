// Used by use_reinit.scad: its top-level assignments run again at every
// call from outside this file.
x = echo("lib x evaluated") 1;
y = x + 1;
function g(a) = echo("g", a) a + y;
function h(n) = n <= 0 ? y : h(n - 1); // calls inside the file: no re-evaluation
module mm(k) { echo(k = k, x = x); children(); }
echo("lib top level: not run by use");

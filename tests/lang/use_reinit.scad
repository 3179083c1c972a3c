// A used file's top-level variables are evaluated afresh at each call into it.
use <lib/reinit_lib.scad>
echo(g(1));
echo(g(2) + g(3));
echo(h(3));
mm(1) mm(2);

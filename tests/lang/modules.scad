// modules with parameters and defaults, children(), $children
module box(size = 2, center = false) { echo(size = size, center = center); cube(size, center); }
box();
box(3);
box(center = true, size = 5);
module count() { echo(n = $children); children(); }
count() { echo("c0"); echo("c1"); echo("c2"); }
count();
module pick(i) children(i);
pick(1) { echo("p0"); echo("p1"); echo("p2"); }
pick([2, 0]) { echo("p0"); echo("p1"); echo("p2"); }
pick([0 : 1]) { echo("p0"); echo("p1"); echo("p2"); }
pick(7) { echo("p0"); }
module sees_dollar() { $inner = 42; children(); }
sees_dollar() echo(inner = $inner);
module nested() { module helper() echo("helper"); helper(); }
nested();
module withvar() { v = 3; children(); }
withvar() { w = 2; echo(w = w); }
echo("done");

// $children and children() in nested modules
module count() echo(children = $children);
count();
count() { cube(); sphere(); }
module pass() count() children();
pass() { cube(); cube(); cube(); }
module each_child() for (i = [0 : $children - 1]) echo(i = i) children(i);
each_child() { echo("zero"); echo("one"); }
module sel() children([0, 2]);
sel() { echo("a"); echo("b"); echo("c"); }
module rng() children([1 : 2]);
rng() { echo("x"); echo("y"); echo("z"); }

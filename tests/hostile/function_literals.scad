f = function(x) function(y) function(z) x + y + z;
echo(f(1)(2)(3));
echo(f(1)(2)(3)(4));
g = function() g;
echo(g()()()());
h = 5;
echo(h(1));

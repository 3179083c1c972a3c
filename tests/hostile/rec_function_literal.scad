f = function(g) g(g);
echo(f(f));

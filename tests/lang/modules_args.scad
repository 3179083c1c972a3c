// module arguments: defaults, positional, named, extra, unknown
module m(a, b = 2, c = a) echo(a = a, b = b, c = c);
m(1);
m(1, 3);
m(c = 5, a = 0);
m(1, 2, 3, 4);
m(d = 1);
m();
module dflt(v = [1, 2], s = "x", f = function(x) x) echo(v, s, f(9));
dflt();

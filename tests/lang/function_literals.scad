// function literals, closures, calls of any expression
sq = function(x) x * x;
echo(sq(5), sq);
fs = [function(x) x + 1, function(x) x * 10, function(x, y = 2) x ^ y];
echo(fs[0](1), fs[1](2), fs[2](3), fs[2](2, 3));
function compose(f, g) = function(x) f(g(x));
echo(compose(sq, fs[0])(3));
function curry(a) = function(b) function(c) a + b + c;
echo(curry(1)(2)(3));
echo((function(x) x * 2)(21));
apply = function(f, v) [for (x = v) f(x)];
echo(apply(sq, [1, 2, 3]));
k = 10;
addk = function(x) x + k;
echo(addk(5));
echo(is_function(sq), is_function(5), is_function(undef));
echo(function(a, b = 3) a + b);
echo(function() [1, "a", true]);

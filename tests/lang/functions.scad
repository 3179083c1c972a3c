// user functions, recursion, defaults, function literals and closures
function fact(n) = n <= 1 ? 1 : n * fact(n - 1);
echo(fact(5), fact(20), fact(170));
function fib(n) = n < 2 ? n : fib(n - 1) + fib(n - 2);
echo([for (i = [0 : 10]) fib(i)]);
function sum(v, i = 0) = i >= len(v) ? 0 : v[i] + sum(v, i + 1);
echo(sum([1, 2, 3, 4]));
function defaults(a, b = 2, c = a) = [a, b, c];
echo(defaults(1), defaults(1, 3), defaults(c = 5, a = 0));
double = function(x) x * 2;
echo(double(4), double);
function adder(n) = function(x) x + n;
add3 = adder(3);
echo(add3(10), adder);
echo(let(a = 2, b = a * 3) a + b);
function count(n) = n <= 0 ? 0 : 1 + count(n - 1);
echo(count(3000));
function f(x) = x;
echo(f(1, 2), f(y = 3));

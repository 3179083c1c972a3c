// function arguments like module arguments
function f(a, b = 2, c = a) = [a, b, c];
echo(f(1), f(1, 3), f(c = 5, a = 0), f(), f(1, 2, 3, 4), f(z = 1));
function g(x = undef) = is_undef(x) ? "none" : x;
echo(g(), g(3), g(undef));
function h(n) = n;
echo(h(n = 7), h(7));

// ordinary recursion: both branches, mutual recursion, recursion in a vector
function fib(n) = n < 2 ? n : fib(n - 1) + fib(n - 2);
echo([for (i = [0 : 15]) fib(i)]);
function is_even(n) = n == 0 ? true : is_odd(n - 1);
function is_odd(n) = n == 0 ? false : is_even(n - 1);
echo(is_even(10), is_odd(7), is_even(3));
function flatten(l) = [for (a = l) each (is_list(a) ? flatten(a) : [a])];
echo(flatten([1, [2, [3, [4, []]], 5], [[6]]]));
function depth(n) = n == 0 ? 0 : 1 + depth(n - 1);
echo(depth(2000));

// Tail recursion stops after 1,000,000 calls, worded as openscad
function f(n) = n <= 0 ? 0 : f(n - 1);
echo(f(1e6));
echo(f(2e6));

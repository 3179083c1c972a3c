// Unbounded non-tail function recursion
function add_up_to(n) = (
    n == 0 ? 0 : n + add_up_to(n - 1)
    );
echo(sum10 = add_up_to(10));
echo(sum = add_up_to(-1));

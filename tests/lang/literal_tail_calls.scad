// A function literal calling itself through its variable in tail position
// runs in a loop, as openscad 2021.01 (no recursion limit at 100,000)
fold = function(i, n) n <= 0 ? i : fold(i + 1, n - 1);
echo(fold(0, 100000));

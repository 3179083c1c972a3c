// assert that holds, as statement and as expression
assert(true);
assert(1 == 1, "never shown");
x = assert(2 > 1) "ok";
echo(x);
function safe_div(a, b) = assert(b != 0, "division by zero") a / b;
echo(safe_div(6, 3));
assert(len([1, 2]) == 2) echo("child of assert");

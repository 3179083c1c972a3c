// for (several variables), let, if/else, echo and assert as statements
for (i = [0 : 1], j = ["a", "b"]) echo(i, j);
for (v = [[1, 2], [3, 4]]) echo(v = v);
for (c = "hé!") echo(c);
for (n = 5) echo(n = n);
for (u = undef) echo("never");
let (a = 1, b = a + 1) echo(a = a, b = b);
if (1 > 2) echo("then"); else echo("else");
if ([]) echo("empty is true"); else if ("s") echo("string is true");
echo(value = 3) echo("nested");
assert(true, "not shown") echo("after assert");
x = 4;
if (x % 2 == 0) { y = x / 2; echo(half = y); }

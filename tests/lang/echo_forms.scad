// echo as a statement and as an expression
echo();
echo("a", 1, [2], undef, true, name = "n");
x = echo("in expression") 5;
echo(x = x);
y = echo(before = 1) echo(again = 2) [1, 2];
echo(y);
echo(str = "named str", v = [1, [2, "s"]]);
echo(echo("inner") "outer");

// Numerals too large for a double make no token (2021.01's lexer drops
// them); a range of exactly 1,000,000 values is refused (issue 18)
echo(1, 1e999, 2);
echo(1e400);
echo(1.7976931348623157e308, 1e-400);
echo(len([for (i = [1:1000000]) i]));
echo(len([for (i = [0:999999]) i]));
for (i = [1:1000000]) if (i == 1) echo("m");
echo(len([each [1:1000000]]));
echo(len([for (i = [1:999999]) i]));

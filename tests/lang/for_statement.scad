// for as a statement: vectors, ranges, strings, several variables, undef
for (i = [1, 2]) echo(i = i);
for (i = [0 : 1], j = ["a", "b"]) echo(i, j);
for (c = "xy") echo(c);
for (i = undef) echo("never");
for (i = 5) echo(single = i);
for (i = []) echo("never");
intersection_for (i = [1 : 2]) echo(ifor = i);

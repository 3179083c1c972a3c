// len and concat over all kinds of values
echo(len([1, 2, 3]), len("abc"), len([]), len(""), len(5), len(undef), len([0 : 3]));
echo(concat([1], [2, 3], 4, "s", [[5]]));
echo(concat(), concat([]), concat(undef), concat([1], undef));
echo(len(concat([for (i = [1 : 100]) i], [for (i = [1 : 100]) i])));

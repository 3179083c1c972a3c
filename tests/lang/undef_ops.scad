// undef with a warning on type mismatch
echo(1 + "a", [1] + 1, "a" * 2, true + 1, undef + 1);
echo(-"x", !undef, [1, 2] * [1, 2, 3]);
echo(1 < "a", "a" < "b", [1] < [2], undef == undef, 1 == true);
echo([1, 2] + [10, 20, 30], [1, [2, 3]] - [1, [1, 1]]);
echo(5 % 3, -5 % 3, 5.5 % 2, 2 ^ 0.5, (-2) ^ 2, -2 ^ 2);

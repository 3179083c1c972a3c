// operators, precedence, and undefined operations
echo(1 + 2 * 3, (1 + 2) * 3, 7 / 2, 7 % 3, -7 % 3, 5.5 % 2, 2 ^ 10, -2 ^ 2, 2 ^ 3 ^ 2);
echo(1 / 0, -1 / 0, 0 / 0, 1 % 0, (-8) ^ (1 / 3), 1e308 * 10);
echo(1 < 2, 2 <= 2, 3 > 4, 4 >= 5, 1 == 1.0, 1 != 2, "a" < "b", "b" >= "a");
echo(true && false, true || false, !true, !0, !"", ![], !undef, 0 || "x", 3 ? "yes" : "no");
echo(1 == true, undef == undef, "1" == 1, [1, 2] == [1, 2], [1, [2]] != [1, [3]]);
echo(true + 1, "a" + "b", undef * 2, "x" - 1);
echo(true < 2, undef < 1, 1 < "a");
echo(-[1, 2, [3]], +5, -(-3));

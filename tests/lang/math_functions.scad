// abs sign ceil floor round ln log exp sqrt pow min max norm cross
echo(abs(-3), sign(-2), sign(0), sign(5), ceil(1.2), floor(-1.2), round(2.5), round(-2.5));
echo(ln(1), log(100), log(2, 8), exp(1), sqrt(16), sqrt(-1), pow(2, 10), pow(-8, 1/3));
echo(min(3, 1, 2), max(3, 1, 2), min([4, 2, 8]), max([4, 2, 8]), min([]), max(5));
echo(min(1, "a"), max("a", "b"), min([1, 2], 3));
echo(norm([3, 4]), norm([1, 2, 2]), norm([]), norm("x"), norm([1, "a"]));
echo(cross([1, 0, 0], [0, 1, 0]), cross([1, 2], [3, 4]), cross([1, 2, 3], [4, 5]));
echo(round(0.5), round(-0.5), round(1e20), ceil(-0.5), floor(0.5));

// builtin math functions
echo(sin(30), cos(60), tan(45), sin(180), cos(90), sin(-90), cos(360), sin(1e10), tan(90));
echo(asin(1), acos(0), atan(1), atan2(1, 1), atan2(-1, -1), asin(2));
echo(abs(-3), ceil(1.2), floor(-1.5), round(0.5), round(-0.5), round(2.5), sign(-3), sign(0));
echo(sqrt(16), sqrt(-1), pow(2, 0.5), exp(1), ln(10), log(100), log(2, 8), ln(0));
echo(min(1, 5, 2), max(1, 5, 2), min([4, 2, 8]), max([4, 2, 8]), min([[1], [2]]), max(["a", "b"]));
echo(min(), min([]), min(1, "a"), max([1, 2], [3]));
echo(norm([3, 4]), norm([1, 2, 2]), norm(5), norm([1, "a"]));
echo(cross([1, 0, 0], [0, 1, 0]), cross([1, 2], [3, 4]));
echo(sin("a"), len(3), len(undef), sqrt(), pow(1));
echo(rands(0, 1, 2, 42), rands(5, 10, 3, 7), rands(0, 1, 0, 1));
echo(lookup(1.5, [[1, 10], [2, 20]]), lookup(0, [[1, 10], [2, 20]]), lookup(3, [[1, 10], [2, 20]]), lookup(1.5, [[2, 20], [1, 10]]));
echo(version(), version_num());

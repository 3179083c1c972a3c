echo(pow(10, 400), exp(1000), ln(0), log(-1), sqrt(-1), 0 / 0 == 0 / 0, 1 / 0 - 1 / 0);
echo(sin(1e300), cos(1 / 0), atan2(0 / 0, 1), acos(2), round(1e308), floor(-1 / 0), sign(0 / 0));
echo(norm([1e308, 1e308]), cross([1, 2], [3, 4]), max([]), min(), abs(-1 / 0), 1e308 % 0, 5 % 0);

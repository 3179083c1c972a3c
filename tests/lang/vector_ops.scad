// vector arithmetic and matrix products
a = [1, 2, 3];
b = [4, 5, 6];
echo(a + b, a - b, a * 2, 2 * a, a / 2, -a, a * b);
m = [[1, 2], [3, 4]];
echo(m * m, m * [1, 1], [1, 1] * m, m * 2);
echo([[1, 2, 3]] * [[1], [2], [3]]);
echo([1, 2] * [1, 2, 3]);
echo([] + [], [[1, 2]] + [[3, 4]], ["a"] + [1]);

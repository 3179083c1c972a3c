function d(l, n) = n == 0 ? l : d(concat(l, l), n - 1);
echo(len(d([1], 40)));

function s(x, n) = n == 0 ? x : s(str(x, x), n - 1);
echo(len(s("ab", 40)));

// libFuzzer slow unit eval-slow-unit-841c6ed7 (a string doubled 40 times): stops at --max-string
function s(x, n) = n == 0 ? x : s(str(x, x), n - 1);
echo(len(s("ab", 40)));

// libFuzzer timeout eval-timeout-dcafd201 (a list doubled 40 times): stops at the step limit
function d(l, n) = n == 0 ? l : d(concat(l, l), n - 1);
echo(len(d([1], 40)));

// tail calls run as loops: 100000 deep through ?:, let, echo and assert
function count(n, acc = 0) = n <= 0 ? acc : let(m = n - 1) count(m, acc + 1);
echo(count(100000));
function down(n) = n == 0 ? "done" : assert(n > 0) down(n - 1);
echo(down(200000));
function loud(n) = n == 0 ? "end" : echo(n) loud(n - 1);
echo(loud(3));
function sum(v, i = 0, acc = 0) = i < len(v) ? sum(v, i + 1, acc + v[i]) : acc;
echo(sum([for (i = [1 : 50000]) i]));

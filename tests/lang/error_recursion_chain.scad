// Mutual recursion through two function literals: 12 TRACE lines
// alternating, the failing call's own frame not among them (issue 18)
chaining1 = function(x) x <= 0 ? 0 : chaining2(x - 1);
chaining2 = function(x) x <= 0 ? 0 : chaining1(x - 1);
echo(chaining = chaining1(500000));

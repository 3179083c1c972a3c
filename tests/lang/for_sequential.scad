// Loops whose later parts see the earlier ones (issue 18)
// C-style for: the updates run in order, each seeing the ones before
echo([for (i = 0, r = 0; i < 3; i = i + 1, r = i * 10) [i, r]]);
echo([for (a = 1, b = 1; a < 50; t = a, a = b, b = t + b) a]);
// later ranges see earlier variables, in modules and comprehensions
for (i = [0:2], j = [i:2]) echo(i, j);
echo([for (i = [0:2], j = [i:2]) [i, j]]);
intersection_for (i = [1:2], j = [i:2]) echo(ij = [i, j]);
// the sign warnings only for literal ranges
n = 5;
for (i = [n:1:0]) echo(i);
for (i = [5:1:0]) echo(i);
for (i = [0:-1:5]) echo(i);
for (i = [5:+1:0]) echo(i);
for (i = [5:1 + 1:0]) echo(i);
// begin not a number: end and step are not evaluated
r = [undef:echo("end") 1:echo("step") 1];
echo(r);

// ranges: construction, iteration, printing
echo([0 : 3], [0 : 2 : 10], [1 : 0.5 : 3], [0 : 0.1 : 0.3]);
echo([for (i = [0 : 0.1 : 0.3]) i], [for (i = [0 : 0.1 : 0.29999]) i]);
echo([3 : 0]);
echo([0 : -1 : 3]);
echo([for (i = [5 : -2 : 0]) i], [for (i = [0 : 0 : 3]) i]);
r = [2 : 3 : 11];
echo(r[0], r[1], r[2], r[3]);
for (i = [1 : 3]) echo(i = i);
echo([for (i = [0 : 2e6]) i]);

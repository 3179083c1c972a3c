// ranges: steps, empty ranges, float steps, reversed, as values
echo([0 : 5], [0 : 2 : 10], [10 : -3 : 0]);
echo([for (i = [0 : 0.1 : 0.5]) i]);
echo([for (i = [0 : 0.25 : 1]) i]);
echo([for (i = [1 : -1 : 5]) i]);
echo([for (i = [5 : 1 : 1]) i]);
echo([for (i = [3 : 3]) i]);
echo([for (i = [0 : 1e-1 : 0.3]) i]);
r = [2 : 3 : 11];
echo(r[0], r[1], r[2], r[3], len(r));
echo([for (i = [-2.5 : 1.5]) i]);
echo([for (i = [1 : 0.5 : 3]) i]);
echo([for (i = [0 : -0.5 : -2]) i]);

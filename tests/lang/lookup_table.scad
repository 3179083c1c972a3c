// lookup(): interpolation, clamping, unsorted tables
t = [[-1, 10], [0, 0], [1, 5], [3, 25]];
echo([for (x = [-2, -1, -0.5, 0, 0.25, 1, 2, 3, 4]) lookup(x, t)]);
echo(lookup(1.5, [[2, 20], [1, 10]]), lookup(0, []), lookup("a", t), lookup(1, 5));
echo(lookup(0.5, [[0, [0, 0]], [1, [10, 20]]]));

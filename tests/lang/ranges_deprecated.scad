// [begin:end] with begin > end is swapped, with a deprecation line
echo([for (i = [5 : 1]) i]);
for (i = [3 : 0]) echo(i);
echo([for (i = [0 : 2 : -4]) i]);
echo([for (i = [4 : -2 : 8]) i]);

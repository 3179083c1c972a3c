// list comprehensions
echo([for (i = [0 : 3]) if (i % 2) i * 10 else -i]);
echo([for (i = [0 : 2], j = [0 : 1]) [i, j]]);
echo([for (i = [0 : 2]) for (j = [0 : i]) j]);
echo([each [1, 2], each [3 : 5], each "ab"]);
echo([for (i = 0; i < 5; i = i + 1) i * i]);
echo([for (i = 0, j = 10; i < 3; i = i + 1, j = j - 1) [i, j]]);
echo([let(a = 2) for (i = [1 : a]) i], [for (i = [1 : 3]) let(s = i * i) s]);
echo([for (c = "abc") c], [for (i = []) i], [for (x = undef) x], [for (x = 5) x]);
echo([for (i = [1 : 4]) if (i > 2) i], [if (true) 1], [if (false) 1 else 2]);
echo([for (i = [0 : 1]) each [i, i]]);

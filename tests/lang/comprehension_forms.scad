// list comprehensions: several variables, C-style for, if/else, let, each, nesting
echo([for (i = [0 : 2], j = [0 : 1]) [i, j]]);
echo([for (i = 0; i < 5; i = i + 1) i * i]);
echo([for (i = 0, j = 10; i < j; i = i + 2, j = j - 1) [i, j]]);
echo([for (i = [1 : 6]) if (i % 2) i else -i]);
echo([for (i = [1 : 6]) if (i % 2 == 0) i]);
echo([for (i = [1 : 3]) let(s = i * i, t = s + 1) [s, t]]);
echo([each [1, 2], each "ab", each [3 : 5]]);
echo([for (i = [0 : 2]) for (j = [0 : i]) j]);
echo([for (a = [[1, 2], [3, 4]]) each a]);
echo([if (true) 1, if (false) 2 else 3]);
echo([for (i = [1, 2]) if (i == 1) for (j = [7, 8]) j else i]);
echo([let(a = 5) for (i = [0 : a - 1]) i]);
echo([for (c = "héllo") c]);
echo([for (x = undef) x], [for (x = 5) x], [for (x = true) x]);

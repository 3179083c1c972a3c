// Function literals printed as openscad 2021.01 prints them (issue 18)
f1 = function(x) [for (i = x) i * 2];
f2 = function(x) [for (i = x) if (i > 1) i else -i];
f3 = function(x) [for (i = x, j = [1:2]) let(k = i + j) [i, j, k]];
f4 = function(x) [each x, for (a = 0; a < 3; a = a + 1) a];
f5 = function(x) [for (i = x) each [i, i]];
f6 = function(x) -x + !x * (x ? 1 : 2) ^ 3 % 2;
f7 = function(x) let(a = 1, b = 2) assert(a) echo(b) x[0].y;
f8 = function(x) [1 : 2 : 3];
f9 = function(x) f1(x)(2);
echo(f1, f2, f3, f4, f5, f6, f7, f8, f9);
f = function(x) [if (x) 1 else 2, if (x) 3];
g = function(x) [for (i = x) let(a = i) a];
h = function(x) [for (i = x) for (j = x) i];
echo(f, g, h);

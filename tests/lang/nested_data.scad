// deep nesting of vectors and strings in echo
echo([[[[1]]], [[], [[]]], "s", ["t", ["u"]]]);
echo([undef, [undef], true, [false]]);
v = [for (i = [0 : 3]) [for (j = [0 : i]) j]];
echo(v, len(v[3]));

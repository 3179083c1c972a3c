// truthiness, short circuit, nested ternaries
vals = [0, 1, -1, "", "a", [], [0], undef, true, false, 0/0];
echo([for (v = vals) v ? 1 : 0]);
echo(true && "x", 0 || [], !0, !"", !!5);
function f(x) = x < 0 ? "neg" : x == 0 ? "zero" : x < 10 ? "small" : "big";
echo(f(-1), f(0), f(5), f(50));
echo(false && undefined_thing, true || undefined_thing);

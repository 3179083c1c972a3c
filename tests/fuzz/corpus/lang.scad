module r(n) { if (n > 0) { cube(n); translate([n,0,0]) r(n-1); } }
r(4);
function f(x) = x <= 0 ? [] : concat([x], f(x-1));
echo(f(5), [for (i=[0:3]) each [i,i]], let(a=1) a, str("x", 1.5));

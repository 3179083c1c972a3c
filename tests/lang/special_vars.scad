// $-variables are scoped dynamically
$fn = 8;
module show() echo(fn = $fn, fa = $fa, fs = $fs, t = $t, preview = $preview);
show();
module wrap() { $fn = 20; show(); }
wrap();
show($fn = 5);
function f() = $x;
module g() echo(f());
$x = 1;
g();
module h() { $x = 2; g(); }
h();
echo($vpr, $vpt, $vpd, $children);
let($x = 3) echo(f());

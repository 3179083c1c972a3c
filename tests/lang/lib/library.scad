use <sub/inner_lib.scad>
lib_secret = 17;
echo("library top level is not run");
function lib_f(x) = x + lib_secret + $q;
module lib_m() echo("lib_m", lib_secret, $q);
module lib_g() echo("lib_g");
function lib_uses_inner() = inner_value();
cube(5);

// use <…> imports only modules and functions; the library sees its own variables
use <lib/library.scad>
$q = 3;
echo(lib_f(1));
lib_m();
echo(lib_secret);
lib_g();
function lib_f(x) = -x;
echo(lib_f(1));
echo(lib_uses_inner());

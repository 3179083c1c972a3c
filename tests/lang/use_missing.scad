// missing libraries and includes are warnings, evaluation goes on
use <no_such_library.scad>
include <no_such_include.scad>
echo("still here");

// A file including itself by any spelling: openscad 2021.01 refuses to
// include a file that is being included (issue 18)
include <include_recursive.scad>
include <../lang/include_recursive.scad>
include <./lib/../include_recursive.scad>
echo("INC");

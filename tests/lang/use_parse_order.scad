// A used file is parsed after the file that uses it (its warnings come
// after the main file's), as openscad 2021.01 (issue 18)
use <lib/use_overwrite.scad>
a = 1;
a = 2;
echo(a, in_use());

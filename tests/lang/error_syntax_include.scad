// A syntax error in an included file: its name and line, then the main file.
echo(1);
include <lib/bad_syntax.scad>
echo(2);

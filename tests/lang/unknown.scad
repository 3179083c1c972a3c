// unknown names give OpenSCAD's warnings and undef / nothing
foo();
foo(1) cube(1);
echo(bar(2), zz);
echo($undefined_special);
x = nothing + 1;
echo(x);
children();
echo("still running");

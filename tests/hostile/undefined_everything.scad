cube(undef_var);
foo();
echo(bar());
x = y + z;
translate(undef) cube();
rotate(undef) undef_module();

// A syntax error at the end of the file: openscad reports the line after.
echo(1);
x = [1, 2][

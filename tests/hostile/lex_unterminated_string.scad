cube();
echo("abc

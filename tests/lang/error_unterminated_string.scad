// A string never closed
a = "text;

echo(a);

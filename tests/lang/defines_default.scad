// values -D would override; here the file's own
size = 10;
name = "box";
echo(size = size, name = name);

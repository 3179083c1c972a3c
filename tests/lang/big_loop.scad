// large but legal loops
echo(len([for (i = [0 : 99999]) i]));
echo(len([for (i = [0 : 0.5 : 50000]) i]));
s = [for (i = [1 : 1000]) i * i];
echo(s[999], len(s));

echo(len(str([for (i = [0:999999]) i])));
echo(len(str([for (i = [0:999999]) "abcdefghij"])));

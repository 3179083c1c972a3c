echo(len(str([for (i = [0:999998]) i])));
echo(len(str([for (i = [0:999998]) "abcdefghij"])));

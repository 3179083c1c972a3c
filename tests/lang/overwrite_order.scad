// a reassigned variable keeps its first position, takes its last value
a = 1;
b = a + 1;
a = 10;
echo(a = a, b = b);
module m() { v = 1; echo(v = v); v = 2; }
m();

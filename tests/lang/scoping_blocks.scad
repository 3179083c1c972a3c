// braces do not open scopes; for and let bodies do
c = 1;
{ c = 2; }
echo(c = c);
for (i = [1 : 2]) { d = i * 10; echo(d = d); }
let (e = 5) { f = e + 1; echo(e = e, f = f); }
module late() { echo(y = y); y = 7; }
late();
z = w + 1;
w = 3;
echo(z = z);

// reassignment warnings, in files, modules and child scopes
a = 1;
echo(a);
a = 2;
module m() {
  b = 1;
  b = 3;
  echo(b);
}
m();
if (true) { c = 1; echo(c); c = 2; }

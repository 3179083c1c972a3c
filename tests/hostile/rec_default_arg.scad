function f(x = f()) = x;
echo(f());

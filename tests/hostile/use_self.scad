use <use_self.scad>
function f() = f();
echo(f());

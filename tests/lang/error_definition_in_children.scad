// Module and function definitions among an instantiation's children are a
// syntax error in 2021.01 (its child_statement has none); in a module's body
// and a bare block they are fine.
module a() { module b() echo("b"); b(); }
{ function g() = 1; }
a();
if (g()) {
    function f() = 2;
    echo(f());
}

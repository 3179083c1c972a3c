// Evaluation order, as openscad 2021.01 shows it through echo() in expressions:
// right operand first, index first, range begin/end/step, defaults before
// arguments, user and builtin-module arguments last to first, duplicates.
echo((echo("a") 1) + (echo("b") 2));
echo((echo("a") 1) * (echo("b") 2));
echo((echo("a") 1) < (echo("b") 2));
echo((echo("a") true) && (echo("b") 2));
echo([(echo("a") 1), (echo("b") 2)]);
echo(-(echo("a") 1));
echo((echo("a") [1,2])[(echo("b") 0)]);
echo(f3((echo("a") 1), (echo("b") 2)));
echo((echo("a") true) ? (echo("b") 1) : 2);
echo((echo("a") 1) == (echo("b") 2));
echo((echo("a") 1) % (echo("b") 2));
echo(str((echo("a") 1), (echo("b") 2)));
function f3(x, y, z) = x + y + z;
echo(f3((echo("a") 1), (echo("b") 2), (echo("c") 3)));
echo(f3(z = (echo("a") 1), x = (echo("b") 2), y = (echo("c") 3)));
echo(f3((echo("a") 1), z = (echo("b") 2), y = (echo("c") 3)));
function g(x = (echo("dx") 1), y = (echo("dy") 2)) = x + y;
echo(g());
echo(g((echo("a") 5)));
module m1(x, y, z) { echo(x, y, z); }
m1((echo("a") 1), (echo("b") 2), (echo("c") 3));
m1(z = (echo("a") 1), x = (echo("b") 2));
echo(max((echo("a") 1), (echo("b") 2)));
h = function(x, y) x + y;
echo(h((echo("a") 1), (echo("b") 2)));
echo((echo("a") 1) - (echo("b") 2) - (echo("c") 3));
echo(let(p = (echo("a") 1), q = (echo("b") 2)) p + q);
echo([for (i = (echo("a") [1,2])) if ((echo("b") i) > 0) i]);
echo([(echo("a") 1) : (echo("b") 2) : (echo("c") 3)]);
cube([(echo("a") 1), (echo("b") 2), 3], center = (echo("c") true));
function f2(x, y) = x + y;
echo(f2((echo("a") 1), (echo("b") 2)));

// Commas openscad 2021.01 accepts: doubled in calls and vectors, trailing
// in vectors and parameter lists, leading in parameter lists
echo([1, 2, ], [1, , 2], [for (i = [1, 2]) i, ]);
function f(a, ) = a;
function g(, a) = a;
module m(, , a, , ) echo(a);
echo(f(1), g(2), 1, , 2);
m(3);

// Expressions as openscad 2021.01 prints them (Expression::print) in
// echoed function literals and failed assertions: string literals
// escaped, a unary plus dropped, a comprehension's let with its body in
// parentheses; and a line break inside a string literal dropped.
echo(function(a) let(b = 1) [for (i = [1]) let(c = "q\"x\t\\") each c, +a]);
echo(function() [let(k = 2) k, for (i = [0:1]) let(j = i) j]);
s = "a
b";
echo(s, len(s));
assert("a\"b\n" == +1);

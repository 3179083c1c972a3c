// rands() as openscad 2021.01: seeds hashed (non-integer, negative, huge,
// NaN), one engine for the run (unseeded calls after a seeded one repeat),
// counts taken by absolute value and truncated, infinite inputs reset with
// its warnings, a non-number argument silently undef (issue 18)
for (s = [0, 1, 1.5, 2.9, -1, -2.5, 1e10, 4294967296.5, -1e10, 1e20, -4.1e-100, 0/0])
    echo(s, rands(0, 1, 2, s));
echo(rands(0, 10, 3, 42), rands(0, 10, 3));
echo(rands(5, 1, 2, 7));
echo(rands(0, 1, 2.7, 7), rands(0, 1, -1, 7), rands(0, 1, 0, 7));
echo(rands(0, 1, "a", 7), rands("a", 1, 1), rands(0, 1, 1, "s"));
echo(rands(3, 3, 3));
echo(rands(0, 1));
echo(rands(0, 1, 1, 2, 3));
echo(rands(1/0, 1, 1, 2));
echo(rands(0, -1/0, 2, 2));
echo(rands(0, 1, 1/0, 3));
echo(rands(0/0, 0/0, 0/0, 0/0));
x = rands(0, 1, 1, 99);
echo(rands(0, 1, 4));

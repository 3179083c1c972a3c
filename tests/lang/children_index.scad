// children() with bad indices: OpenSCAD's two warnings, and C's (int)
// conversion on x86-64 for NaN and huge values (INT_MIN: "negative").
module m() {
    children(5);
    children(-1);
    children(1e300);
    children(0 / 0);
    children(-5);
    children(0.7);
    children([7, -2, 0]);
}
m() { cube(1); sphere(1); }
echo(rands(0, 1, 2, 0 / 0) == rands(0, 1, 2, 0));

// cylinder()'s ambiguous radii; assert() without a condition looks one up;
// search() with too few arguments (issue 18)
cylinder(h=5, r=5, r1=0);
cylinder(h=5, d=5, r=1);
cylinder(h=5, d1=5, r1=1);
cylinder(h=5, d2=5, r2=1);
cylinder(h=5, d=5, r1=2);
cylinder(h=5, r=5, d1=2);
cylinder(h=5, r=5, d1=2, d2=3);
cylinder(h=5, d=5, d1=2, d2=3);
cylinder(h=5, r1=5, d1=2);
echo(search(1));
module m() assert(message = "m");
condition = true;
assert();

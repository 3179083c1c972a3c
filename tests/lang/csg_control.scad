// control statements as groups in the dump
for (i = [0 : 2]) translate([i, 0, 0]) cube();
intersection_for (i = [0 : 1]) rotate(i * 30) cube();
if (true) cube(); else sphere();
if (false) cube();
if (false) cube(); else sphere();
let(s = 2) cube(s);
echo("x") cube();
echo("empty");
assert(true) sphere();
module two() { cube(); sphere(); }
two();
module none() { }
none();
module kids() children();
kids() { cube(); sphere(); }
module first() children(0);
first() { cube(); sphere(); }

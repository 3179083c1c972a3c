// A warning repeated in a row is printed 5 times, as openscad 2021.01;
// ordering ranges; 'operation undefined' for two undefs or functions (issue 18)
module d(t) { if (t > 0) cube(); }
for (a = [0:10:50]) d(false);
for (a = [0:10:50]) d(false);
for (i=[0:9]) echo(true > 1);
for (i=[0:9]) { echo(true > 1); echo(true < 1); }
for (i=[0:9]) echo(x);
echo(true > 1);
for (i=[0:9]) echo("e");
f = function(x) x; g = function(x) x;
echo(f < g, undef > undef, [0:1:3] < [0:1:4], [0:1:3] >= [0:1:3], [1:1:3] > [0:1:9], [5:1:0] < [0:1:1], f < 1);

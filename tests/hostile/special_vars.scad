$fn = "abc";
$fa = [1, 2];
$fs = undef;
$t = 1 / 0;
sphere(5);

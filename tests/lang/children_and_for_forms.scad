// for () without arguments instantiates nothing; children() of a range over
// 10,000 values or of a string is refused with openscad 2021.01's warnings;
// linear_extrude scales that are not finite are no scale (issue 18)
for () cube();
translate([10, 0, 0]) for () sphere();
module lineup(num) for (i = [0 : num - 1]) translate([i, 0, 0]) children([0:10000]);
lineup(2) { cube(); sphere(); }
module str_child() children("test");
str_child() cube();
for (s = [1/0, -1/0, 0/0, [1, 1/0], [2, 3], 2, undef]) linear_extrude(height = 1, scale = s) square(1);

// $fn/$fa/$fs resolved on every shape that uses them
$fn = 10;
sphere();
module m() { $fs = 0.5; sphere(); cylinder(); }
m();
circle($fn = 3);
translate([1, 0, 0]) { $fa = 5; sphere(); }
linear_extrude(height = 1, $fn = 6) circle();

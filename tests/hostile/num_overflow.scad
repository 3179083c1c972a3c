x = 1e308 * 10;
echo(x, -x, x - x);
cube(x);
translate([x, 0, 0]) cube();

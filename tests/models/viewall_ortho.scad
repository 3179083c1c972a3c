// args: --imgsize=300,200 --camera=0,0,0,55,0,25,10 --viewall --autocenter --projection=o
$fn = 96;
translate([40, 20, 5]) scale([3, 1, 1]) sphere(5);
translate([30, 20, 0]) cube([20, 2, 2]);

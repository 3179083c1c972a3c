// args: --imgsize=320,240 --camera=2,0,0,60,0,30,70
$fn = 96;
sphere(r = 8);
translate([14, 0, 0]) sphere(d = 8);

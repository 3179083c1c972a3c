// args: --imgsize=300,300 --camera=0,0,0,55,0,25,50
$fn = 96;
intersection_for (n = [0:2]) {
    rotate([0, 0, n * 60]) cube([20, 8, 8], center = true);
}

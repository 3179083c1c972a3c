// args: --imgsize=300,300 --camera=0,0,0,70,0,30,60
$fn = 96;
intersection() {
    cube(12, center = true);
    sphere(8);
}

// args: --imgsize=400,400 --camera=0,0,0,60,0,30,70
// A transparent shell around an opaque core: the core must show through.
$fn = 128;
color("crimson") cube(8, center = true);
color([0.3, 0.6, 1.0], 0.3) difference() {
    sphere(12);
    sphere(11);
}

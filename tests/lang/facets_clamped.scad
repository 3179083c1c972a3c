// $fs and $fa below 0.01: the primitives clamp them with a warning, the
// extrusions keep them as given (issue 18)
cylinder($fs=0);
cylinder($fa=0);
cylinder($fs=0.001, $fa=0.001);
sphere($fs=-1);
circle($fa=0);
linear_extrude(1, $fs=0) circle(1);
rotate_extrude($fa=0) translate([2,0]) circle(1);
circle($fs=0,$fn=5);

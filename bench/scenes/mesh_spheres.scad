// meshing: the union of two spheres r = 10 whose centres are 10 apart.
// Exact volume 2·(4/3)π·10³ − π(4r + d)(2r − d)²/12 = 7068.583471.
fn = 64;
union() {
    sphere(10, $fn = fn);
    translate([10, 0, 0]) sphere(10, $fn = fn);
}

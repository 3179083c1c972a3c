// meshing: cube(20) minus sphere(11) minus three r = 6.5 cylinders along the axes.
// Exact volume 2404.778358 (REFERENCE.md).  $fn for OpenSCAD comes from -D fn=….
fn = 64;
difference() {
    cube(20, center = true);
    sphere(11, $fn = fn);
    cylinder(r = 6.5, h = 30, center = true, $fn = fn);
    rotate([90, 0, 0]) cylinder(r = 6.5, h = 30, center = true, $fn = fn);
    rotate([0, 90, 0]) cylinder(r = 6.5, h = 30, center = true, $fn = fn);
}

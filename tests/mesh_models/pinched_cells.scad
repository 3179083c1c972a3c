// A faceted sphere minus a faceted cylinder: cells where the surface
// passes twice, whose two loop vertices both sat at the same corner of the
// cell (8 such points in this mesh), which every STL reader welds into a
// vertex with two fans.  Now each loop keeps a point of its own.
difference() {
    sphere(r = 10, $fn = 12);
    rotate([90, 0, 0]) cylinder(h = 30, r = 6, center = true, $fn = 12);
}

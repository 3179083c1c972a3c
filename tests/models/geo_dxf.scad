// args: --imgsize=400,300 --camera=30,12,0,50,0,20,120
// import() of a hand-written DXF (tests/models/data/geo_dxf.dxf): a closed
// LWPOLYLINE plate with a CIRCLE, an ARC closed by a LINE, a BLOCK's
// triangle placed by INSERT and an ELLIPSE as holes (even-odd); its
// thickness from dxf_dim() and a pin at dxf_cross(); the same layer again
// with origin, scale and $fn.
h = dxf_dim(file = "data/geo_dxf.dxf", name = "thick");
c = dxf_cross(file = "data/geo_dxf.dxf", layer = "cross");
linear_extrude(height = h) import("data/geo_dxf.dxf", layer = "plate");
translate([c[0], c[1], h]) cylinder(r = 1.5, h = 4, $fn = 24);
translate([36, 0, 0]) linear_extrude(height = 3, twist = 30)
    import(file = "data/geo_dxf.dxf", layer = "plate", origin = [-2, 4], scale = 0.8, $fn = 7);

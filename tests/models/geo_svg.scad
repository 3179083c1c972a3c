// args: --imgsize=400,300 --camera=60,0,0,25,0,0,380
// import() of hand-written SVGs (tests/models/data/geo_svg*.svg) as
// OpenSCAD 2021.01 reads them: viewBox and mm page, nested transforms,
// path commands, basic shapes, strokes; a page without viewBox at two dpi,
// one centred.
linear_extrude(height = 4) import("data/geo_svg.svg");
translate([0, -30, 0]) linear_extrude(height = 2) import("data/geo_svg_plain.svg", dpi = 96);
translate([100, -50, 0]) linear_extrude(height = 3)
    import(file = "data/geo_svg_plain.svg", center = true);

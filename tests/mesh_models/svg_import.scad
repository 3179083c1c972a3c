// import() of an SVG (tests/models/data/geo_svg_plain.svg: a rect, a
// triangle with a triangular hole, a stroked quadratic curve), extruded,
// once on the page at dpi 96 and once centred.
linear_extrude(height = 2) import("../models/data/geo_svg_plain.svg", dpi = 96);
translate([0, -40, 0]) linear_extrude(height = 3)
    import(file = "../models/data/geo_svg_plain.svg", center = true);

// args: --imgsize=400,300 --camera=2,2,10,55,0,25,75
// surface(): a text heightmap (comments, a blank line, a ragged row) and an
// RGB PNG (luminance × 100/255), OpenSCAD's polyhedron: four triangles a
// cell, walls down to one below the lowest height.
translate([-12, 0, 0]) scale([1.5, 1.5, 1]) surface("data/surface.dat", center = true);
translate([4, -3, 0]) scale([1.2, 1.2, 0.12]) surface(file = "data/surface.png");
translate([4, 6, 12]) scale([1.2, 1.2, 0.05]) surface("data/surface.png", invert = true);

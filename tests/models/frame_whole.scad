// args: --imgsize=400,300
// openscad's preview draws render(), resize() and extrusions as one piece
// of geometry and frames that piece's box, not the boxes of the leaves
// inside: each sphere here is cut to a cube, and the frame is the cubes'.
resize([0, 0, 0]) intersection() { sphere(r = 14); cube(10, center = true); }
translate([16, 0, 0]) render() intersection() { sphere(r = 14); cube(10, center = true); }
translate([0, 16, 0]) linear_extrude(5) intersection() { circle(r = 14); square(10, center = true); }

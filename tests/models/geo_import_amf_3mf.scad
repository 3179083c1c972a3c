// args: --imgsize=400,300 --camera=0,0,0,60,0,30,140
// import() of AMF and 3MF (tests/models/data/make_data.sh): the part and the
// prism as openscad exports them; a zipped AMF of two overlapping objects
// (unioned), one with a vertex per triangle corner; a 3MF of two mesh
// objects whose build items move one of them, which 2021.01 ignores.
translate([-14, 10, 0]) import("data/part.amf");
translate([14, 10, 0]) import("data/hex.3mf");
translate([-20, -20, 0]) import("data/two_boxes.amf");
translate([16, -16, 0]) import("data/post.3mf");

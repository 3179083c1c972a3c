// import() of AMF and 3MF (tests/models/data/make_data.sh): the part as
// openscad exports it, a zipped AMF of two overlapping objects (unioned)
// and a 3MF of two mesh objects whose build transform 2021.01 ignores.
import("../models/data/part.amf");
translate([0, 20, -5]) import("../models/data/two_boxes.amf");
translate([0, -22, -5]) scale(1.5) import("../models/data/post.3mf");

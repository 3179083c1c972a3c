// args: --imgsize=400,300 --camera=0,0,0,60,0,30,90
// import() of an STL and of an OFF with OpenSCAD's one-line header ("OFF nv
// nf 0"), both written by openscad (tests/models/data/make_data.sh); scale
// is ignored for meshes, as in OpenSCAD 2021.01.
translate([-12, 0, 0]) import("data/part.stl", convexity = 3);
translate([12, 0, 0]) rotate([0, 0, 30]) import(file = "data/hex.off", scale = 4);

// Malformed AMF and 3MF files (generate.py writes them): each import warns
// with its location and draws what OpenSCAD 2021.01 would, never crashes.
translate([0, 0, 0]) import("data/garbage.amf");
translate([2, 0, 0]) import("data/empty.amf");
translate([4, 0, 0]) import("data/not_a_number.amf");
translate([6, 0, 0]) import("data/index_out_of_range.amf");
translate([8, 0, 0]) import("data/index_overflow.amf");
translate([10, 0, 0]) import("data/nan_inf.amf");
translate([12, 0, 0]) import("data/truncated.amf");
translate([14, 0, 0]) import("data/second_object_broken.amf");
translate([16, 0, 0]) import("data/empty_element.amf");
translate([18, 0, 0]) import("data/no_triangles.amf");
translate([20, 0, 0]) import("data/entities.amf");
translate([22, 0, 0]) import("data/deep.amf");
translate([24, 0, 0]) import("data/zip_two_entries.amf");
translate([26, 0, 0]) import("data/zip_garbage.amf");
translate([28, 0, 0]) import("data/missing.amf");
translate([30, 0, 0]) import("data/garbage.3mf");
translate([32, 0, 0]) import("data/empty.3mf");
translate([34, 0, 0]) import("data/no_model.3mf");
translate([36, 0, 0]) import("data/index_out_of_range.3mf");
translate([38, 0, 0]) import("data/truncated.3mf");
translate([40, 0, 0]) import("data/missing.3mf");

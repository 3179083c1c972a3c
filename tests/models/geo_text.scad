// args: --imgsize=500,250 --camera=20,-6,0,0,0,0,110
// text(): default font, alignment, size, spacing, extruded.
text("rayscad", size = 8);
translate([0, -14]) text("Ag&Q", size = 10, halign = "center", valign = "center");
translate([30, -14]) linear_extrude(2) text("12", size = 6, spacing = 1.5, $fn = 32);

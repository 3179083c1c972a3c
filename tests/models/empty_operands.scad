// args: --imgsize=480,240
// Empty operands, as openscad 2021.01 draws them: every module
// instantiation is a node, and an empty one is an operand (an intersection
// with it is empty, so is a difference whose first operand it is), while
// echo(), assert(), an if() without a taken branch and children() of an
// absent child are no node at all (but children() of any child is a group:
// case() of echo() is empty).  Row y = 0 must show nothing but the marker
// cube; row y = 20 shows one cube per case.
module none() {}
module kids() children();
module pick() intersection() { children(3); cube(6, center = true); }
module case(i) translate([i * 10, 0, 0]) intersection() { children(); cube(6, center = true); }
case(0) for (i = []) cube(1);
case(1) union() {}
case(2) group() {}
case(3) color("red") {}
case(4) cube(0);
case(5) sphere(0);
case(6) import();
case(7) none();
case(8) kids();
case(9) let (a = 1) {}
case(10) render() {}
case(11) linear_extrude(1) {}
case(12) translate([1, 0, 0]) {}
case(13) if (false) cube(1); else {}
case(14) hull() {}
case(15) for (i = [1]) if (false) cube(1);
case(16) echo("a group of nothing");
translate([0, 0, 0]) difference() { union() {} cube(6, center = true); }
translate([-10, 0, 0]) cube(2, center = true); // marker
translate([0, 20, 0]) {
    intersection() { echo("not an operand"); cube(6, center = true); }
    translate([10, 0, 0]) intersection() { assert(true); cube(6, center = true); }
    translate([20, 0, 0]) intersection() { if (false) cube(1); cube(6, center = true); }
    translate([30, 0, 0]) pick() cube(1);
    translate([40, 0, 0]) intersection() { *cube(1); cube(6, center = true); }
    translate([50, 0, 0]) difference() { cube(6, center = true); union() {} }
}

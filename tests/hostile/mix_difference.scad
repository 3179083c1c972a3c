difference() { square(3); cube(); }
translate([5, 0, 0]) difference() { cube(3); circle(); }

hull() { cube(); translate([3, 0, 0]) circle(); }

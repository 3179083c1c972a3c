difference() { square(4); translate([1,1]) square(1); }
rotate_extrude($fn=12) translate([3,0]) circle(1);

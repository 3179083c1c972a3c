// modifiers keep their node in the tree (csg) and echo as usual
#cube(1);
%sphere(2);
*cylinder(h = 3);
translate([1, 0, 0]) #rotate(30) cube(2);
echo("modifiers");

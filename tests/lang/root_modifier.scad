// ! makes its subtree the whole model
cube(5);
!translate([1, 2, 3]) sphere(1);
echo("root");

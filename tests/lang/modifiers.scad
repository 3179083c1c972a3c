// modifiers: * disables (no echo), ! # % still evaluate
*echo("disabled");
*union() { echo("disabled too"); }
#cube(1);
%sphere(1);
%echo("background echo");
#echo("highlight echo");
translate([5, 0, 0]) !cube(2);
echo("end");

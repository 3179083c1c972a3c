$vpd = 0 / 0;
$vpr = [1 / 0, 0, 0];
$vpt = "x";
sphere(5);

// One usable $vp* value turns --viewall off, with its warning
$vpr = [10, 20, 0, 30];
$vpd = 200;
cube();

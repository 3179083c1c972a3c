// args: --imgsize=300,300 --camera=0,0,0,30,0,40,60 --projection=o
cube(10, center = true);

for (i = [0:1e7]) cube(1);

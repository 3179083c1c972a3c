intersection_for (i = [0:1e7]) cube(i);
intersection_for (i = [0:1 / 0]) sphere();

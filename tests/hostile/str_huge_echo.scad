echo([for (i = [0:999998]) i]);

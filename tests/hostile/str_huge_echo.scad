echo([for (i = [0:999999]) i]);

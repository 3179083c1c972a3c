for (i = [0:1000]) for (j = [0:1000]) for (k = [0:1000]) if (i + j + k < 0) cube();

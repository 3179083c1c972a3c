// A lone sphere: smooth everywhere, no sharp feature.
sphere(r = 10, $fn = 96);

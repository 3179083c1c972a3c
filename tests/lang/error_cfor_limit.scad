// A C-style for that never ends: an error after 1,000,000 iterations
echo([for (i = 0; true; i = i + 1) i]);

assert();
assert(1 / 0);
assert(0 / 0, [1, 2]);

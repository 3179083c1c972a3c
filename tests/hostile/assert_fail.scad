cube();
assert(false, "this model asserts");

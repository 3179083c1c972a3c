// text() at a size whose FreeType 26.6 value is no long: a warning, nothing drawn (converting it was undefined behaviour, found by fuzz_pipeline)
text("x", size = 1e300);
text("y", size = -1e300);
cube(1);

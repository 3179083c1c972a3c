include <deeper.scad>
nested_value = deeper_value + 1;

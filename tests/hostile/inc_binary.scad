include <gen_garbage_1.scad>
cube();

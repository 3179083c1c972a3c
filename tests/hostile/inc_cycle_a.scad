include <inc_cycle_b.scad>
cube();

include <inc_cycle_a.scad>
sphere();

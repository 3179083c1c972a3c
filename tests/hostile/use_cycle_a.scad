use <use_cycle_b.scad>
module a() b();
a();

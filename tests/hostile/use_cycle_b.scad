use <use_cycle_a.scad>
module b() a();
b();

include <inc_self.scad>
cube();

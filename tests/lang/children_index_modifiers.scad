// A modifier on children(i) with a number i is lost in 2021.01: the call
// returns the child's own node, not one of its own that would carry the
// '%' or '#'.  children() and children([i]) keep theirs.
module bg_all() %children();
module bg_first() %children(0);
module bg_list() %children([0]);
module hl_first() #children(0);
bg_all() cube(1);
bg_first() cube(2);
bg_list() cube(3);
hl_first() cube(4);
i = 0;
module bg_var() %children(i);
bg_var() sphere(1);

module m() { children(5); children(-1); children(1e300); children(0 / 0); children([0:1e9]); children([5, -1, "a"]); children("x"); }
m() cube();
children();
children(0);

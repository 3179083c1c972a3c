render(convexity = 1 / 0) cube();
render(convexity = -1) group() cube();
group() group() group();
union() { }
difference() { }
intersection() { }
difference() { sphere(); }
intersection() { cube(); }

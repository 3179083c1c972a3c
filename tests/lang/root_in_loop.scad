// One root statement in a loop is one root: no warning
for (i = [0:10]) !sphere();

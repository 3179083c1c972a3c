for (i = [0:1 / 0]) cube();
for (i = [0:0:1]) cube();
for (i = [0:-1:10]) cube();
for (i = [0 / 0:1:3]) cube();
for (i = [-1 / 0:1 / 0]) cube();
echo([for (i = [0:1 / 0]) i]);

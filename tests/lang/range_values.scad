// Ranges as openscad 2021.01: equality by begin, step and count (empty
// ones equal), the first value begin itself, zero/infinite/NaN steps (issue 18)
echo(a=[0:1:3] == [0:1:3.5], b=[0:1:3] == [0:1:3], c=[0:2:0] == [0:5:0], d=[5:1:0] == [7:1:0], e=[0:0/0:1] == [1:0/0:2], f=[0:1:1/0] == [0:1:1/0], g=[0:0:1]==[0:0:1], h=[0:1/0:5]==[0:1/0:7], i=[1:1/0:5]==[0:1/0:5], j=[0:1:3]==[0:1:2], k=[0:1:3] != [0:1:3.5], l=[0:2:4]==[0:2:5], m=[0:0:1]==[0:0:2]);
echo([for (i=[3:1/0:5]) i], [for (i=[-0:1:0]) 1/i], [for (i=[0:-0.5:-1]) i]);
r = [0:0/0:1/0];
echo(r, r[0], r[1], r[2], is_list(r), len(r));
echo([0:0/0:1/0] == [0:0/0:1/0], r == r);
echo([0:0:5], [0:1/0:5], [0:-1/0:5]);
for (i = [0:0:2]) echo(z=i);
for (i = [0:1/0:2]) echo(inf=i);
for (i = [0:0/0:2]) echo(nan=i);
echo([for (i = [0:0:2]) i], [for (i = [0:1/0:2]) i], [for (i = [5:1/0:2]) i]);
echo([for (i = [0:1:1/0]) i][0]);

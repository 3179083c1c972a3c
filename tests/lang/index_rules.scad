// indexing: vectors, strings, ranges, fractional and bad indices
v = [10, 20, 30];
echo(v[0], v[1.7], v[-1], v[3], v["a"], v[undef], v[true]);
echo("abc"[1], "abc"[5], [0 : 2 : 8][1], v.x, v.y, v.z, [1, 2].z);
m = [[1, 2], [3, 4]];
echo(m[1][0], m[0].y, m[5][0]);
echo(undef[0], 5[0]);

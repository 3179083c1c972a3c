// args: --imgsize=400,300 --camera=0,0,0,55,0,35,60
// polyhedron(): the manual's cube, and an L-shaped prism whose end faces are
// single concave hexagons (fan-triangulated, counted by signed crossings).
CubePoints = [[0, 0, 0], [10, 0, 0], [10, 7, 0], [0, 7, 0],
              [0, 0, 5], [10, 0, 5], [10, 7, 5], [0, 7, 5]];
CubeFaces = [[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4],
             [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]];
polyhedron(CubePoints, CubeFaces);
L = [[0, 0], [8, 0], [8, 2], [2, 2], [2, 8], [0, 8]];
translate([-12, 0, 0])
polyhedron(points = concat([for (p = L) [p[0], p[1], 0]], [for (p = L) [p[0], p[1], 6]]),
           faces = concat([[0, 1, 2, 3, 4, 5]], [[11, 10, 9, 8, 7, 6]],
                          [for (i = [0:5]) [i, i + 6, (i + 1) % 6 + 6, (i + 1) % 6]]));

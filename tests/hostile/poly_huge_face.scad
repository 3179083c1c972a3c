n = 100000;
polyhedron(points = [for (i = [0:n - 1]) [cos(i * 360 / n), sin(i * 360 / n), 0]],
           faces = [[for (i = [0:n - 1]) i]]);
